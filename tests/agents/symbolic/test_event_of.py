"""After a request, "need a copy of the new signing": an office verb's "-ing" after "of" and a
determiner names an occasion, not a paper, so the clause is why the request is made
(screen/event_of.py), never a photocopy asked about or a print. A thing of the office after
"of" is still asked, and the clause alone is read as before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office
from helpers.dataset_offices import default_office


@pytest.fixture(scope="module")
def default_parser() -> InstructionParser:
    return InstructionParser(default_office())


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        # asked what to do with the photocopy before
        ("Would you mind fetching Wang's stapler for me? Need a copy of the new signing", "wang"),
        ("bring me a stapler, need a copy of the new printing at the desk", None),
        ("bring me a stapler, need a copy of the booking", None),  # read so already
    ],
)
def test_a_thing_of_an_occasion_is_why(
    default_parser: InstructionParser, text: str, owner: str | None
) -> None:
    frame = default_parser.parse(text, "lee")
    assert frame.question is None and frame.decline is None, (text, frame)
    assert [(t.item, t.owner) for t in frame.tasks] == [("stapler", owner)], text


@pytest.mark.parametrize(
    "text",
    [
        "bring me a stapler, need a copy of my contract",
        "bring me a stapler, need a copy of the printing schedule",  # "printing" modifies
    ],
)
def test_a_paper_is_still_asked(default_parser: InstructionParser, text: str) -> None:
    tasks = default_parser.parse(text, "lee").tasks
    assert [(t.kind, t.item) for t in tasks] == [("transfer", "stapler"), ("copy", "document")]


def test_alone_it_is_read_as_before(default_parser: InstructionParser) -> None:
    frame = default_parser.parse("need a copy of the new signing at the desk", "lee")
    assert frame.question is not None and not frame.tasks


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("could you bring me a ruler? need a scan of the latest printing", ["ruler"]),  # printed
        ("could you bring me a ruler? need a photo of the new signing", ["ruler"]),
        ("could you bring me a ruler? need a scan of my contract", ["ruler", "document"]),
    ],
)
def test_in_harbour(harbour: Office, text: str, items: list[str]) -> None:
    frame = InstructionParser(harbour).parse(text, "may")
    assert frame.question is None and [t.item for t in frame.tasks] == items, (text, frame)
