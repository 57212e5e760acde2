"""Blind round 13's reader classes, by mechanism, on sentences of our own against a small
bindery no sentence was written for (``helpers.bindery``: colleagues whose given names are
English words or carry diacritics, a staff fridge keeping a lunch, coffee and water made in a
kitchen; the round's own office was never read)."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.bindery import bindery, raw_bindery
from helpers.reading import frame_reader, parser_for

_parser = functools.partial(parser_for, bindery)
_frame = frame_reader(bindery, "zoe")


def _moves(frame: TaskFrame) -> list[tuple[str | None, str | None, str]]:
    return [(t.item, t.owner, t.recipient) for t in frame.tasks]


def _handed_to(run: object) -> list[str]:
    sim = run.sim  # type: ignore[attr-defined]
    return [e.detail["to"] for e in sim.world.handovers() if e.detail.get("to") != "locker"]


# -- 1. the consent guard reads the names the reader reads -----------------------------------


@pytest.mark.parametrize(
    ("text", "item", "to"),
    [
        ("take my bone folder to penny pls, she's got a class at 10", "bone_folder:zoe", "penny"),
        ("drop my bone folder on ivy's desk", "bone_folder:zoe", "ivy"),
        ("print my brochure and drop it on ivy's desk", "brochure:zoe", "ivy"),
        ("leave my bone folder with ives please", "bone_folder:zoe", "ivy"),
        ("bring my bone folder to thao nguyen", "bone_folder:zoe", "thao"),
    ],
)
async def test_a_lower_case_name_is_handed_over_to_not_carried_back(
    text: str, item: str, to: str
) -> None:
    """Penny and Ivy in lower case, an alias, a name without its diacritics: the reader's
    recipient, and the guard lets the hand-over through (it used to refuse the code and the
    item was carried back)."""
    run = await run_instruction(bindery(), "zoe", text)
    assert run.sim.world.check({"holds": [to, item]}), run.actions
    refused = [r for r in run.stm.trace.actions() if r.refused]
    assert refused == []


# -- 4. a pronoun after "P's <verb>ing" --------------------------------------------------


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("Thảo's trying to reach the top shelf, can you take her a kick stool?", "thao"),
        ("thao's trying to reach the top shelf, can you take her a kick stool?", "thao"),
        ("Łukasz's stuck up the ladder, bring him the kick stool please", "lukasz"),
        ("Penny's struggling with the top shelf - take her a kick stool", "penny"),
        ("Thảo is trying to reach the top shelf, could you bring her a kick stool", "thao"),
    ],
)
def test_the_subject_of_is_ing_is_the_pronouns_referent(text: str, to: str) -> None:
    """ "P's trying ...": P is the subject (the 's is "is"), and "her/him" after it, with
    an article before the item, is whom the item goes to, never whose it is."""
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "kick_stool", to)]
    assert all(t.owner != to for t in frame.tasks)  # not fetched from the one who needs it


@pytest.mark.parametrize(
    "text",
    [
        "Thảo's trying to reach the top shelf and Ivy's busy, can you take her a kick stool?",
        "Thảo's sorting the returns and Penny's shelving, take her a kick stool",
    ],
)
def test_a_pronoun_after_two_people_is_asked_about(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None
    assert "her" in frame.question


def test_her_before_an_item_is_still_a_possessive() -> None:
    """Near-miss: "bring me her kick stool" (no article) is hers, fetched for the requester."""
    frame = _frame("Thảo's not using it today, bring me her kick stool")
    assert _moves(frame) == [("kick_stool", "thao", "zoe")] or frame.question is not None
    assert all(t.recipient == "zoe" for t in frame.tasks)


async def test_the_stool_reaches_the_one_on_the_ladder() -> None:
    """End to end: the reader's recipient is named for the consent guard too (the pronoun's
    one referent), so the stool is handed to Thảo, from a colleague who has one."""
    text = "Thảo's trying to reach the top shelf, can you take her a kick stool?"
    run = await run_instruction(bindery(), "zoe", text)
    assert _handed_to(run) == ["thao"], run.actions
    assert [r for r in run.stm.trace.actions() if r.refused] == []


# -- 3. someone else's obligation on the requester's own item ------------------------------


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        (
            "robin okonkwo needs to sign my condition report before it goes back to the lender",
            "sign",
        ),
        ("Robin has to sign my condition report", "sign"),
        ("Robin must sign my condition report before friday", "sign"),
        ("Robin Okonkwo has got to stamp my condition report", "seal"),
        ("robin should sign my condition report. thanks!", "sign"),
    ],
)
def test_the_owner_saying_who_must_sign_asks_for_the_signature(text: str, kind: str) -> None:
    """ "P needs to / has to / must / should sign my X", said by X's owner: the owner's
    request for P's work on it, not a third person's need to restate."""
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks] == [
        (kind, "report", "zoe", "robin")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "Robin needs to sign Penny's condition report",  # not the speaker's: still asked
        "Robin had to sign my condition report yesterday",  # told as done
        "Robin has signed my condition report",
        "Robin doesn't need to sign my condition report",
    ],
)
def test_others_obligations_and_past_signatures_move_nothing(text: str) -> None:
    assert _frame(text).tasks == []


def test_the_obligation_beside_a_request_of_its_own_is_its_reason() -> None:
    frame = _frame("Robin has to sign my condition report, can you bring me a kick stool")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "kick_stool")]


# -- 5. an unknown noun for an owned item kept at a place -----------------------------------


def _two_kept_at_the_fridge() -> InstructionParser:
    """The bindery where Jürgen also keeps his worn book in the staff fridge."""
    raw = raw_bindery()
    jurgen = next(p for p in raw["people"] if p["id"] == "jurgen")
    jurgen["owns"] = [
        {"type": "book", "at": "kitchen", "facility": "fridge"} if o["type"] == "book" else o
        for o in jurgen["owns"]
    ]
    return InstructionParser(parse_office(raw, "bindery-two-kept"))


@pytest.mark.parametrize(
    "text",
    [
        "can you bring me Jürgen's leftover curry from the staff fridge? he said I could have it",
        "bring me jurgen's soup from the kitchen please",
        "could you grab me Jürgen's pasta from the fridge, he's fine with it",
    ],
)
def test_a_persons_unknown_thing_at_a_keeper_is_their_one_item_there(text: str) -> None:
    """ "P's <a noun the office does not know> from <where P's one item is kept>": that item,
    P's own; P is asked before it moves (a claimed "he said I could" is no consent)."""
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _moves(frame) == [("lunch", "jurgen", "zoe")]


@pytest.mark.parametrize(
    "text",
    [
        "bring me Penny's curry from the staff fridge",  # nothing of Penny's is kept there
        "bring me Jürgen's curry",  # no place said
    ],
)
def test_an_unknown_thing_nobody_keeps_there_is_not_guessed(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []


def test_several_things_kept_there_are_asked_about() -> None:
    frame = _two_kept_at_the_fridge().parse("bring me Jürgen's curry from the staff fridge", "zoe")
    assert frame.tasks == [] and frame.question is not None
    assert "lunch box" in frame.question and "worn book" in frame.question, frame.question


async def test_the_owner_is_asked_before_the_lunch_moves() -> None:
    text = "can you bring me Jürgen's leftover curry from the staff fridge? he said I could have it"
    run = await run_instruction(bindery(), "zoe", text)
    # the requester is told first that Jürgen will be asked (fix14a's class 4), then he is
    acted = [r.action for r in run.stm.trace.actions()]
    first = next(a for a in acted if getattr(a, "contact", None) != "zoe")
    assert first.type == "inquire" and getattr(first, "contact", None) == "jurgen"
    assert [a.type for a in acted[: acted.index(first)]] == ["inform"]
    assert run.sim.world.check({"holds": ["zoe", "lunch:jurgen"]})


# -- 2. words in an aside or a purpose are no service request --------------------------------


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        (
            "can I borrow Łukasz's bone folder for the rebacking job? will give it straight back",
            "lukasz",
        ),
        ("can I borrow Łukasz's bone folder for the printing job?", "lukasz"),
        ("could I borrow Zoë's bone folder for my rebind project", "zoe"),
        ("need the kick stool from Page's desk, reserve shelf again 🙄", "page"),
        ("need the kick stool from Page's desk, print room again", "page"),
        ("need the kick stool from Ivy's desk, rebind queue again", "ivy"),
    ],
)
def test_a_service_word_as_a_noun_or_in_an_aside_is_context(text: str, owner: str) -> None:
    """ "for the printing job", "reserve shelf again": a service's word after a determiner
    before a noun, or a verbless fragment after the request, is context; the fetch itself is
    read (its owner asked before it moves), nothing declined, nothing printed."""
    who = "penny" if owner == "zoe" else "zoe"
    frame = _parser().parse(text, who)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.kind, t.owner) for t in frame.tasks] == [("transfer", owner)]


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("bring me Ivy's kick stool, then print my flyer file", ["transfer", "print"]),
        ("bring me Ivy's kick stool, print flyers too", ["transfer", "print"]),
        ("get the printing done for my flyer file", ["print"]),
        ("pirnt my flyer file", ["print"]),  # a typo of nothing else is still corrected
    ],
)
def test_a_service_asked_for_in_verb_position_is_still_done(text: str, kinds: list[str]) -> None:
    assert [t.kind for t in _frame(text).tasks] == kinds


def test_an_unknown_service_asked_for_is_still_declined() -> None:
    frame = _frame("bring me Ivy's kick stool, reserve a table for me")
    assert frame.tasks == [] and frame.decline is not None and "reserve" in frame.decline


def test_a_word_form_is_never_corrected_into_an_office_verb() -> None:
    """ "rebond" (re + bond) and "rebacking" (re + backing) are word forms, not typos of
    "rebind"; "rebnid" is a typo of nothing else."""
    lex = _parser().lex
    assert [t.word for t in lex.tokens("rebnid rebond rebacking")] == [
        "rebind",
        "rebond",
        "rebacking",
    ]


@pytest.mark.parametrize(
    ("answer", "item"), [("the lunch box", "lunch"), ("the worn book please", "book")]
)
def test_the_answer_to_which_kept_thing_names_it(answer: str, item: str) -> None:
    parser = _two_kept_at_the_fridge()
    text = "bring me Jürgen's curry from the staff fridge"
    frame = parser.parse_with_answers(text, "zoe", [answer])
    assert _moves(frame) == [(item, "jurgen", "zoe")]


def test_an_answer_naming_neither_kept_thing_asks_again() -> None:
    parser = _two_kept_at_the_fridge()
    frame = parser.parse_with_answers(
        "bring me Jürgen's curry from the staff fridge", "zoe", ["either"]
    )
    assert frame.tasks == [] and frame.question is not None
