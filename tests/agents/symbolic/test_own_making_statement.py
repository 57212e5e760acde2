"""A thing the speaker says they made, in a statement before the request ("I finished the
seating chart for Friday, can you print it for me?", "just wrote up the minutes - could you
print them?"), is the speaker's own file, and the request's "it"/"them" points at it (blind
round 59's class, analogue): it asked which file "it" meant. Also where the message opens
with the verb, a verb that is a colleague's name ("drew up the floor plan", with Drew in the
office). Another's making ("Tam finished the seating chart") is never the speaker's own (a
thing said to be theirs, "Tam's seating chart is done, print it", is theirs: they are asked
for it), and a thing the office has that is no file ("I made the coffee") is read as before."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.antecedent import WHICH_FILE
from helpers.events_desk import events_desk
from helpers.reading import frame_reader

_frame = frame_reader(events_desk, "ines")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("I finished the seating chart for Friday, can you print it for me?", "ines"),
        ("just wrote up the minutes - could you print them?", "ines"),
        ("I drew up the floor plan for the new booth, can you print it for me?", "ines"),
        ("drew up the floor plan for the new booth, can you print it for me?", "ines"),
        ("I've just put together the running order. print it and take it to Tam please", "tam"),
        ("ive finally finished the seating plan, print it pls", "ines"),
        ("Finally typed up the guest list! Could you print it out for me", "ines"),
    ],
)
def test_the_speakers_own_making_is_what_it_means(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", "file", "ines", recipient)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Tam finished the seating chart, can you print it for me?",
        "tam wrote up the minutes - could you print them?",
        "can you print it for me?",
    ],
)
def test_anothers_making_or_nothing_said_still_asks_which_file(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.question is not None and frame.question.startswith(WHICH_FILE), frame


@pytest.mark.parametrize(
    "text",
    [
        "Tam's seating chart is done, can you print it for me?",
        "Tam finished her seating chart, can you print it for me?",
        "tam finished his seating chart - could you print it?",
    ],
)
def test_a_thing_said_to_be_anothers_is_theirs_never_the_speakers(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert frame.question is not None or [(t.kind, t.owner) for t in frame.tasks] == [
        ("print", "tam")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Tam finished my seating chart, can you print it for me?",
        "Tam's here. print my file for me",
    ],
)
def test_the_speakers_own_said_as_mine_stays_theirs(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.owner) for t in frame.tasks] == [("print", "ines")], frame


def test_a_thing_the_office_has_that_is_no_file_is_not_the_speakers_file() -> None:
    frame = _frame("I finished the tape measure, can you take it back to Wren")
    assert all(t.item != "file" for t in frame.tasks), frame


async def test_end_to_end_the_speakers_file_is_printed_and_handed_to_them() -> None:
    text = "I finished the seating chart for Friday, can you print it for me?"
    run = await run_instruction(events_desk(), "ines", text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    handed = [
        (e.detail["item"].partition(":")[0], e.detail["to"]) for e in run.sim.world.handovers()
    ]
    assert ("printout", "ines") in handed, trace.summary
