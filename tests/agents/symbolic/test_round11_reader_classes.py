"""Blind round 11's reader classes, by mechanism, on sentences of our own against a small
letterpress studio no sentence was written for (``helpers.printshop``, with a pulping bin
added where a test needs one) and against the default office (the round's own office was
read only to name the classes)."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, load_office, parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.printshop import raw_printshop


def _with_pulping_bin() -> Office:
    """The studio with a service that takes papers away: the "secure waste bin" pulps a
    proof (a consuming service at a facility whose name is also a waste container's); its
    belongings declare what they are for (a bone folder creases, a loupe magnifies); a label
    printer makes label sheets from an artwork file, as the printer makes printouts."""
    raw = raw_printshop()
    for t in raw["item_types"]:  # what each belonging is for, as an office file declares it
        t["purposes"] = {"bone_folder": ["crease", "fold"], "loupe": ["inspect", "magnify"]}.get(
            t["id"], []
        )
    raw["operations"].append(
        {"id": "pulp", "name": "pulp", "verbs": ["pulp"], "input": "proof", "consumes": True}
    )
    raw["facilities"].append(
        {
            "id": "waste_bin",
            "name": "secure waste bin",
            "synonyms": ["pulping bin"],
            "location": "press_room",
            "operations": ["pulp"],
            "guards": ["ugo"],
        }
    )
    raw["item_types"].append(
        {"id": "label_sheet", "name": "labels", "kind": "product", "synonyms": ["label sheet"]}
    )
    raw["operations"].append(
        {
            "id": "label",
            "name": "label",
            "verbs": ["label"],
            "input": "artwork",
            "product": "label_sheet",
        }
    )
    raw["facilities"].append(
        {
            "id": "label_printer",
            "name": "label printer",
            "location": "press_room",
            "operations": ["label"],
            "guards": ["ugo"],
            "products": ["label_sheet"],
        }
    )
    return parse_office(raw, "printshop-pulp")


@functools.cache
def _parser(name: str) -> InstructionParser:
    office = {"printshop": _with_pulping_bin, "default": load_office}[name]()
    return InstructionParser(office)


def _frame(office: str, text: str, who: str) -> TaskFrame:
    return _parser(office).parse(text, who)


# -- 1. disposal by a verb the reader does not know; a thing put where nothing is ----------


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("printshop", "kofi", "chuck Lena's loupe in the skip, it's scratched"),
        ("printshop", "kofi", "ditch Edda's creaser in the bin please"),
        ("printshop", "noor", "could you pop Kofi's bone folder into the rubbish?"),
        ("printshop", "noor", "just stick my loupe in the trash"),
        ("printshop", "edda", "lob Noor's magnifier in a dumpster"),
        ("default", "wang", "chuck Zhang's stapler in the bin, it's broken"),
    ],
)
def test_a_thing_put_into_a_waste_container_is_declined(office: str, who: str, text: str) -> None:
    """Whatever the verb, a thing put into a bin, skip or rubbish is thrown away: declined
    like "throw away ...", never read as fetching it for the requester."""
    frame = _frame(office, text, who)
    assert frame.tasks == []
    assert frame.decline is not None and "won't" in frame.decline, frame.decline


@pytest.mark.parametrize(
    ("who", "text", "item"),
    [
        ("kofi", "put my proof in the secure waste bin", "proof"),
        ("kofi", "pulp my proof in the pulping bin please", "proof"),
    ],
)
def test_an_office_facility_named_like_a_bin_is_its_service(who: str, text: str, item: str) -> None:
    """A bin the office declares as its facility is no rubbish: the errand runs there."""
    frame = _frame("printshop", text, who)
    assert frame.decline is None and frame.question is None, (frame.decline, frame.question)
    assert [(t.item, t.operation) for t in frame.tasks] == [(item, "pulp")]


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("printshop", "kofi", "chuck Lena's loupe in the van"),
        ("printshop", "kofi", "stick Edda's creaser in the cupboard"),
        ("printshop", "noor", "put Kofi's bone folder on the shelf"),
        ("default", "wang", "shove Zhang's stapler in the drawer"),
    ],
)
def test_a_thing_put_where_nothing_of_the_office_is_asks(office: str, who: str, text: str) -> None:
    """A verb that is no errand, and a place that is no person, room or facility: what to
    do is asked, nothing moves (before: a fetch of the thing for the requester)."""
    frame = _frame(office, text, who)
    assert frame.tasks == [] and frame.decline is None
    assert frame.question is not None and "Who should I bring it to?" in frame.question
    assert "_" not in frame.question  # no internal ids


@pytest.mark.parametrize(
    ("who", "text", "item", "owner", "recipient"),
    [
        # "a loupe": any one will do ("the loupe in the press room", where none is kept,
        # is asked about: test_round14_reader_classes)
        ("kofi", "bring me a loupe from the press room", "loupe", None, "kofi"),
        ("kofi", "chuck me Lena's loupe", "loupe", "lena", "kofi"),
        ("kofi", "leave Lena's loupe on Edda's desk", "loupe", "lena", "edda"),
        ("kofi", "grab me the creaser from the bin", "bone_folder", None, "kofi"),
    ],
)
def test_errands_with_a_place_phrase_stay_errands(
    who: str, text: str, item: str, owner: str | None, recipient: str
) -> None:
    """A known errand verb reads its place phrase as where the thing is; a dative "me" or a
    person's desk says who gets it."""
    frame = _frame("printshop", text, who)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, recipient)
    ]


# -- 2. a withdrawal, then a need of the withdrawn thing: its reason, not a new errand -----


@pytest.mark.parametrize(
    ("who", "text"),
    [
        ("kofi", "pulp my old proof... actually scratch that, I still need it"),
        ("kofi", "post my proof to the client. forget it, I need it for the audit"),
        ("edda", "engrave my artwork file. never mind, we still want it as it is"),
        ("noor", "pulp my proofs, actually no, cancel that, I need them"),
    ],
)
def test_a_need_of_what_was_withdrawn_is_its_reason(who: str, text: str) -> None:
    """ "I still need it" after "scratch that": "it" is the thing of the withdrawn request,
    kept; nothing is done and nothing is asked (before: "whose proof?")."""
    frame = _frame("printshop", text, who)
    assert frame.tasks == [] and frame.question is None, frame.question
    assert frame.decline is not None and "did nothing" in frame.decline


@pytest.mark.parametrize(
    ("who", "text", "item"),
    [
        ("kofi", "pulp my old proof. never mind, I need a loupe instead", "loupe"),
        ("kofi", "scratch that, I still need it. bring me a creaser", "bone_folder"),
    ],
)
def test_a_request_after_the_withdrawal_is_still_read(who: str, text: str, item: str) -> None:
    frame = _frame("printshop", text, who)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, who)]


# -- 5. "P has to sign my X": P signs; "can you sort that" asks for it ---------------------


@pytest.mark.parametrize(
    ("office", "who", "text", "actor", "item"),
    [
        ("printshop", "kofi", "Lena has to sign my proof, can you sort that", "lena", "proof"),
        ("printshop", "kofi", "Edda must sign my layout, could you arrange it?", "edda", "proof"),
        ("printshop", "noor", "Ugo needs to sign my proof sheet, sort it out pls", "ugo", "proof"),
        ("printshop", "noor", "Ravi ought to sign my proof, can you handle that", "ravi", "proof"),
        ("default", "wang", "Zhang has to sign my contract, can you sort that", "zhang", None),
    ],
)
def test_the_one_obliged_to_sign_is_the_signer(
    office: str, who: str, text: str, actor: str, item: str | None
) -> None:
    """An obligation ("has to", "must", "ought to") before a person's work names its doer,
    and a request that names nothing of its own ("sort that") asks for that work."""
    frame = _frame(office, text, who)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    [task] = frame.tasks
    assert (task.kind, task.actor, task.owner, task.recipient) == ("sign", actor, who, who)
    if item is not None:
        assert task.item == item


def test_a_request_of_its_own_after_the_obligation_is_read_alone() -> None:
    """ "Lena has to sign my proof, can you bring me a loupe": the statement is context; the
    request names its own thing."""
    frame = _frame("printshop", "Lena has to sign my proof, can you bring me a loupe", "kofi")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "loupe")]


# -- 4. a thing asked for by its purpose in a question, then "bring it over" ---------------


@pytest.mark.parametrize(
    ("office", "who", "text", "item"),
    [
        (
            "printshop",
            "kofi",
            "got anything I can crease this card with? bring it over",
            "bone_folder",
        ),
        (
            "printshop",
            "noor",
            "is there something to inspect this plate with? fetch it pls",
            "loupe",
        ),
        ("default", "wang", "got anything I can trim this ribbon with? bring it over", "scissors"),
    ],
)
def test_a_question_for_a_thing_by_its_purpose_names_the_requests_it(
    office: str, who: str, text: str, item: str
) -> None:
    """The question names the thing by what it is for; the item type declared for that
    purpose is what the request's "it" means (before: not understood)."""
    frame = _frame(office, text, who)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, who)]


def test_the_purpose_question_alone_is_answered_and_offered() -> None:
    frame = _frame("printshop", "got anything I can crease this card with?", "noor")
    assert frame.tasks == []
    assert frame.question is not None and "Edda Lund" in frame.question
    assert frame.question.endswith("Shall I bring you one?")


# -- 3. "the labels are in my file, run them off": the product named picks the operation ---


@pytest.mark.parametrize(
    ("who", "text", "operation", "recipient"),
    [
        (
            "kofi",
            "the new labels are ready in my artwork file, run them off and bring them to Lena",
            "label",
            "lena",
        ),
        ("noor", "my svg has the shop labels, run them off for Edda", "label", "edda"),
        ("kofi", "my prints are in my artwork file, run them off for Lena", "print", "lena"),
    ],
)
def test_the_product_a_statement_names_picks_the_operation(
    who: str, text: str, operation: str, recipient: str
) -> None:
    """The statement names the product by a word that is also a service's verb ("labels",
    "prints") and the file it is in; "them" is the file, made into that product by the
    operation that makes it from a file (before: the file was forwarded)."""
    frame = _frame("printshop", text, who)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("artwork", who, recipient, operation)
    ]


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("print my artwork file as labels for Lena", "label"),
        ("could you print my svg into label sheets for Lena", "label"),
        ("print my artwork file for Lena", "print"),
    ],
)
def test_what_a_file_is_made_into_picks_the_operation(text: str, operation: str) -> None:
    """ "print X as labels": the print verb is the means, the product after "as"/"into" is
    what is made; one task, not a plain print and the labels both."""
    frame = _frame("printshop", text, "kofi")
    assert [(t.item, t.recipient, t.operation) for t in frame.tasks] == [
        ("artwork", "lena", operation)
    ]
