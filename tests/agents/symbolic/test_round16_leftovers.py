"""Blind round 16, class 4: the leftovers of the last round, by mechanism, on a small
newsroom no sentence was written for (``helpers.newsroom``; the round's office and sentences
were never read): an abbreviation's stop ends no sentence; "leave it on my desk" after a
delivery is where it goes; a place of the office after "take it to" is kept; a category with
one thing proposes it plainly; a variant the office does not make is never dropped silently."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.newsroom import newsroom, raw_newsroom

Row = tuple[str, str | None, str | None, str | None, str | None]


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(newsroom())


def _frame(text: str, who: str = "ines") -> TaskFrame:
    return _parser().parse(text, who)


def _rows(frame: TaskFrame) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks]


# -- 1. an abbreviation's stop ends no sentence ------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "get my proof signed by Dr. Adeyemi and then stamped",
        "get my proof signed by Dr. Femi Adeyemi and then stamped please",
        "get my proof signed by Mr. Adeyemi, then get it stamped",
    ],
)
def test_both_parts_after_a_title_with_a_stop_are_done(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.actor) for t in frame.tasks] == [
        ("sign", "page_proof", "femi"),
        ("seal", "page_proof", None),
    ]


@pytest.mark.parametrize(
    "text",
    [
        "have my proof signed by Mr. Adeyemi, then get it stamped",
        "have my proof signed by Femi, then get it stamped",
    ],
)
def test_have_the_thing_done_is_a_request_not_a_question(text: str) -> None:
    """ "have my proof signed by ...": "have", the thing, a task word's participle asks for
    the work (it was read as a question, and only the stamp was done)."""
    frame = _frame(text)
    assert [(t.kind, t.actor) for t in frame.tasks] == [("sign", "femi"), ("seal", None)]


@pytest.mark.parametrize(
    "text",
    ["have the proofs arrived", "have you signed my proof?", "have my proof signed by Femi?"],
)
def test_have_as_a_question_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


def test_a_title_with_a_stop_names_the_doer() -> None:
    frame = _frame("please have Mr. Reyes stamp my proof")
    assert [(t.kind, t.actor) for t in frame.tasks] == [("seal", "tomas")]


def test_a_real_sentence_end_after_a_name_still_ends_it() -> None:
    frame = _frame("get my proof signed by Dr. Adeyemi. Then bring it to Tomas")
    assert [(t.kind, t.actor, t.recipient) for t in frame.tasks] == [("sign", "femi", "tomas")]


@pytest.mark.parametrize(
    "text", ["did Dr. Adeyemi sign my proof?", "Dr. Adeyemi signed my proof, thanks"]
)
def test_a_title_in_a_question_or_thanks_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


def test_a_title_before_the_subject_of_a_statement_is_no_request() -> None:
    """ "Dr. Adeyemi signed my proof": the title is no verb, the sentence tells a fact."""
    for text in ("Dr. Adeyemi signed my proof, thanks", "Dr Adeyemi signed my proof"):
        assert _frame(text).tasks == [], text


# -- 2. "leave it on her desk" after a delivery is where it goes --------------------------------


@pytest.mark.parametrize(
    ("text", "who", "item", "to"),
    [
        ("Marta needs my proof. Leave it on her desk", "ines", "page_proof", "marta"),
        ("Marta needs my proof, leave it on her desk", "ines", "page_proof", "marta"),
        ("Ines needs a pen, leave it in her office", "tomas", "pen", "ines"),
        (
            "can you take my proof to Marta? Just leave it on her desk",
            "ines",
            "page_proof",
            "marta",
        ),
        ("can you get me a pen? Just leave it on my desk", "ines", "pen", "ines"),
        ("bring Tomas my lanyard. Leave it in his office", "ines", "lanyard", "tomas"),
    ],
)
def test_leaving_it_at_someones_place_is_the_delivery(
    text: str, who: str, item: str, to: str
) -> None:
    frame = _frame(text, who)
    assert frame.question is None, frame.question
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, to)]


@pytest.mark.parametrize(
    "text",
    [
        "leave her alone",
        "keep everyone away from my proof",
        "leave my lanyard where it is",
        "I'll leave it on her desk",
        "leave my lanyard in the stationery cupboard",
    ],
)
def test_leave_as_a_wish_or_a_plan_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == [], text


# -- 3. a place of the office a thing is taken to is kept --------------------------------------


@pytest.mark.parametrize(
    ("text", "place", "keeper"),
    [
        ("print my agenda and take it to the post room", "to the post room", "Hana Sato"),
        ("print my agenda and then take it to the legal desk", "to the legal desk", "Oskar"),
        ("print my agenda, take it to Desk 3", "to Desk 3", "Femi Adeyemi"),
    ],
)
def test_a_place_taken_to_is_asked_about_never_dropped(text: str, place: str, keeper: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None
    assert place in frame.question and keeper in frame.question


@pytest.mark.parametrize(
    ("answer", "to"), [("Hana", "hana"), ("to Hana", "hana"), ("Hana Sato please", "hana")]
)
def test_the_person_there_named_in_the_answer_gets_it(answer: str, to: str) -> None:
    frame = _parser().parse_with_answers(
        "print my agenda and take it to the post room", "ines", [answer]
    )
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "agenda", to)]


@pytest.mark.parametrize(
    ("text", "rows"),
    [
        ("take my proof to the legal desk", [("heat", "page_proof", "ines", "ines", None)]),
        ("bring me a pen from the stationery cupboard", [("transfer", "pen", None, "ines", None)]),
        ("print my agenda and bring it to Hana", [("print", "agenda", "ines", "hana", None)]),
    ],
)
def test_a_place_a_task_goes_to_is_read_as_before(text: str, rows: list[Row]) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert _rows(frame) == rows


# -- 4. a category with one thing -----------------------------------------------------------


def _one_of_each() -> InstructionParser:
    """The newsroom whose kitchen makes only coffee, and where Ines keeps a sandwich in the
    kitchen (a personal thing, the office's one thing to eat)."""
    raw = raw_newsroom()
    raw["item_types"] = [t for t in raw["item_types"] if t["id"] != "tea"]
    raw["item_types"].append({"id": "sandwich", "name": "sandwich", "kind": "personal"})
    raw["operations"] = [o for o in raw["operations"] if o["id"] != "steep"]
    for f in raw["facilities"]:
        if f["id"] == "kitchen_counter":
            f["operations"], f["products"] = ["brew"], ["coffee"]
    for p in raw["people"]:
        if p["id"] == "ines":
            p["owns"].append({"type": "sandwich", "at": "kitchen", "facility": "kitchen_counter"})
    return InstructionParser(parse_office(raw, "newsroom-one-of-each"))


_ONE = functools.cache(_one_of_each)


@pytest.mark.parametrize(
    ("text", "item", "kind"),
    [
        ("bring me something to write with", "pen", "transfer"),
        ("could you get me something to write with please", "pen", "transfer"),
        ("bring me a drink", "coffee", "produce"),
        ("could you get me a hot drink?", "coffee", "produce"),
    ],
)
def test_the_one_thing_of_a_category_nobody_owns_is_what_was_asked_for(
    text: str, item: str, kind: str
) -> None:
    frame = _ONE().parse(text, "ines")
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [(kind, item, "ines")]


def test_the_one_thing_of_a_category_someone_owns_is_offered_plainly() -> None:
    frame = _ONE().parse("bring me something to eat", "ines")
    assert frame.tasks == []
    assert frame.question == "I can get you a sandwich. Would you like that?"
    assert "Which would you like" not in frame.question


def test_yes_to_the_offer_asks_for_it_and_no_does_nothing() -> None:
    yes = _ONE().parse_with_answers("bring me something to eat", "ines", ["yes please"])
    # the request is now for a sandwich, a personal thing: whose, as for "a sandwich"
    assert yes.tasks == [] and yes.question == "Whose sandwich do you mean?"
    no = _ONE().parse_with_answers("bring me something to eat", "ines", ["no thanks"])
    assert no.tasks == [] and no.decline is not None


def test_several_things_of_a_category_are_still_asked_about() -> None:
    frame = _frame("bring me a drink")
    assert frame.tasks == [] and frame.question is not None
    assert "coffee" in frame.question and "tea" in frame.question


@pytest.mark.parametrize("text", ["does the kitchen have a drink?", "I don't need a drink"])
def test_a_category_in_a_question_or_a_negation_moves_nothing(text: str) -> None:
    assert _ONE().parse(text, "ines").tasks == []


# -- 5. a variant the office does not make ------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        ("can I get a herbal tea", "herbal tea"),
        ("bring me a black coffee", "black coffee"),
        ("could you make me a green tea?", "green tea"),
        ("a mint tea please", "mint tea"),
    ],
)
def test_a_variant_known_as_a_thing_of_its_own_is_asked_about(text: str, asked: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None
    assert asked in frame.question and "ordinary" in frame.question


def test_yes_makes_the_plain_one_and_no_nothing() -> None:
    yes = _parser().parse_with_answers("bring me a black coffee", "ines", ["yes please"])
    assert [(t.kind, t.item) for t in yes.tasks] == [("produce", "coffee")]
    no = _parser().parse_with_answers("bring me a black coffee", "ines", ["no"])
    assert no.tasks == [] and no.decline is not None


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("bring me a strong coffee", "coffee"),
        ("a nice hot tea please", "tea"),
        ("a tea please", "tea"),
        ("could you get me a large coffee", "coffee"),
    ],
)
def test_a_quality_is_made_as_before(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", item)]


def test_a_variant_the_office_names_is_its_own_item() -> None:
    raw = raw_newsroom()
    for t in raw["item_types"]:
        if t["id"] == "tea":
            t["synonyms"] = ["herbal tea"]
    frame = InstructionParser(parse_office(raw, "newsroom-herbal")).parse(
        "can I get a herbal tea", "ines"
    )
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "tea")]
