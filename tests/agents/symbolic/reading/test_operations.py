"""After the frames: the office's operation named from the words, declined when none fits the
item, and a send-out service's place outside taken from the readings or asked for."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.operations import WHERE_TO, OperationChooser
from assistantx.agents.symbolic.reading.readings import MentionReader
from assistantx.core.office import Office
from assistantx.core.task_schema import Task, TaskFrame
from helpers.boathouse import boathouse


@pytest.fixture(scope="module")
def office() -> Office:
    return boathouse()  # charge (headlamps) and courier (forms, sent out) share a shape


def choose(office: Office, text: str, item: str) -> TaskFrame:
    """The stage on a task of ``item``, given the lexicon's and the readings' output."""
    lex = Lexicon.from_office(office)
    lexed = lex.read(text)
    outside = MentionReader(office, lex).read(lexed).outside
    frame = TaskFrame(requester="bram", tasks=[Task(kind="heat", item=item, recipient="bram")])
    return OperationChooser(office).choose(frame, lexed, outside)


def test_the_operation_the_verb_names_is_set(office: Office) -> None:
    frame = choose(office, "charge my headlamp", "headlamp")
    assert [t.operation for t in frame.tasks] == ["charge"]


def test_an_item_no_operation_takes_is_declined_with_what_it_is_for(office: Office) -> None:
    frame = choose(office, "charge my radio", "radio")
    assert frame.tasks == []
    assert frame.decline == "Sorry, I can't charge a radio here: I can only charge headlamps."


def test_a_send_out_service_asks_where_to_unless_the_readings_found_it(
    office: Office,
) -> None:
    asked = choose(office, "courier my form", "form")
    assert asked.question is not None and asked.question.startswith(f"{WHERE_TO}courier it to?")
    sent = choose(office, "courier my form to the rowing club in Putney", "form")
    assert [(t.operation, t.destination) for t in sent.tasks] == [
        ("courier", "the rowing club in Putney")
    ]
    # since fix59d: "the rowing club" alone is a kind of place (a participle and a noun, as
    # "the main lab"), not which one nor at what address: asked (bare_place)
    bare = choose(office, "courier my form to the rowing club", "form")
    assert bare.question is not None and bare.question.startswith(f"{WHERE_TO}courier it to?")


def _two_makers() -> Office:
    """A printer and a laminator that both make something from a file, the laminator's
    service asked for as "make a laminated copy"."""
    from assistantx.core.office import parse_office
    from helpers.swab_clinic import raw_swab_clinic

    raw = raw_swab_clinic()
    for op in raw["operations"]:
        if op["id"] == "laminate":
            op["verbs"] = ["laminate", "make a laminated copy"]
    return parse_office(raw)


@pytest.mark.parametrize(
    ("text", "operations"),
    [
        # two services by two verbs: the product named after "make" took both (only the
        # laminated copy was made)
        ("print my report and make a laminated copy from it too", ["print", "laminate"]),
        ("make a laminated copy from my report and print it", ["laminate", "print"]),
        # must not change: one service each
        ("make a laminated copy from my report", ["laminate"]),
        ("print my report", ["print"]),
    ],
)
def test_two_services_said_by_their_own_verbs_are_two_tasks(
    text: str, operations: list[str]
) -> None:
    from assistantx.agents.symbolic.reading.parser import InstructionParser

    frame = InstructionParser(_two_makers()).parse(text, "ines")
    assert [t.operation for t in frame.tasks] == operations, frame
