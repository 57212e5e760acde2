"""A paper of the requester's said by a name the office does not list, after "the", to be
printed for the requester ("can u print me the fire drill plan, the printer's miles away from
my office", "print the fire drill plan for me") is the requester's paper, restated before
anything is done ("Shall I print your file for you?"), as "print my fire drill plan" is (blind
round 57's class; its offices and sentences were never read). "miles away" is a distance, not a
colleague. With nobody it is for, "the <unknown>" is still asked about."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, parse_office
from helpers.bursary import raw_bursary


@functools.cache
def _parser() -> InstructionParser:
    """The bursary, its file a paper one (no electronic file to send on)."""
    raw = raw_bursary()
    for item in raw["item_types"]:
        if item["id"] == "file":
            item["kind"] = "personal"
    office: Office = parse_office(raw, "bursary with paper files")
    return InstructionParser(office)


@pytest.mark.parametrize(
    "text",
    [
        "can u print me the fire drill plan, the printer's miles away from my office",
        "print me the fire drill plan",
        "print the fire drill plan for me",
        "could you print me the staff rota please",
        "print me my fire drill plan",
    ],
)
def test_the_unnamed_paper_printed_for_the_speaker_is_theirs(text: str) -> None:
    frame = _parser().parse(text, "ana")
    assert frame.tasks == [] and frame.question == "Shall I print your file for you?", frame
    taken = _parser().parse_with_answers(text, "ana", ["yes"])
    assert [(t.item, t.owner, t.recipient, t.operation) for t in taken.tasks] == [
        ("file", "ana", "ana", "print")
    ], taken


@pytest.mark.parametrize("text", ["print the fire drill plan", "bring me the fire drill plan"])
def test_with_nobody_it_is_for_or_no_work_on_papers_it_is_not_guessed(text: str) -> None:
    frame = _parser().parse(text, "ana")
    assert frame.tasks == [] and frame.question != "Shall I print your file for you?", frame


def test_the_papers_own_name_is_read_as_before() -> None:
    frame = _parser().parse("print me the file", "ana")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("file", "ana", "ana")], frame
