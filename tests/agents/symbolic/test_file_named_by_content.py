"""Words before a file's name say which file (its topic), never a kind the office does not
make (screen/content_named.py): in an office whose scan to PDF makes the office's files,
"Wang's budget planning file" is Wang's file forwarded, not "a budget planning electronic
file is not something this office makes", and not the requester's paper scanned
(reading/_kinds.py: a colleague's file, or "the file" said again after a task on a file, is
that file, never a new one made from a paper). A made thing with no input ("iced tea") still
asks for a kind."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office
from helpers.dataset_offices import default_office, default_office_that_scans


@pytest.fixture(scope="module")
def scanning() -> InstructionParser:
    return InstructionParser(default_office_that_scans("scan", "file"))


def _tasks(parser: InstructionParser, text: str, who: str) -> list[tuple[str, str, str, str]]:
    frame = parser.parse(text, who)
    assert frame.question is None and frame.decline is None, (text, frame)
    return [(t.kind, t.item, t.owner or "", t.recipient or "") for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "can I get Wang's budget planning file?",  # asked of a variant, then scanned
        "can I get the budget file off Wang",
        "send me Wang's sales forecast file",
        "can I get Wang's file?",  # scanned Lee's paper before
    ],
)
def test_a_colleagues_file_is_forwarded(scanning: InstructionParser, text: str) -> None:
    assert _tasks(scanning, text, "lee") == [("send_file", "file", "wang", "lee")], text


def test_the_file_said_again_is_the_one_printed(scanning: InstructionParser) -> None:
    text = "print my quarter end report and send the file to Wang too"
    assert _tasks(scanning, text, "lee") == [
        ("print", "file", "lee", "lee"),
        ("send_file", "file", "lee", "wang"),
    ]


@pytest.mark.parametrize(
    "text",
    [
        "scan my contract and send the file to Wang",  # the file made of the paper scanned
        "can I get a file of my contract?",  # a file made of the requester's paper
    ],
)
def test_a_file_made_of_a_paper_is_still_a_scan(scanning: InstructionParser, text: str) -> None:
    (task,) = scanning.parse(text, "lee").tasks
    assert (task.operation, task.item, task.owner) == ("scan", "document", "lee"), text


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("can I get Wang's budget planning file?", "wang"),
        ("print my report and send the file to Wang too", "lee"),
    ],
)
def test_default_office_unchanged(text: str, owner: str) -> None:
    tasks = InstructionParser(default_office()).parse(text, "lee").tasks
    assert tasks[-1].kind == "send_file" and tasks[-1].owner == owner, text


@pytest.mark.parametrize(
    "text", ["can I get Mark's budget planning file?", "can I get the budget file off Mark"]
)
def test_harbour(harbour: Office, text: str) -> None:
    tasks = _tasks(InstructionParser(harbour), text, "may")
    assert tasks == [("send_file", "file", "mark", "may")], text


def test_a_kind_of_a_thing_made_from_nothing_is_still_asked(harbour: Office) -> None:
    frame = InstructionParser(harbour).parse("an iced tea please", "may")
    assert not frame.tasks and "iced tea is not something" in (frame.question or "")
