"""A recipient named in apposition to a receiving phrase: "print off my lesson plan for the
cover teacher, Ms Okafor" (blind rounds 57-58's class: the dataset's optimal-policy check
failed on such a base instruction, 11 actions instead of 12, because the consent guard did not
count the name after the comma as named to receive, so the hand-over was refused; the reader
read the printout as the requester's own). "for"/"to" + a determiner and a few words ending in
a noun (the person's role), a comma, then the name closing its clause: the name is who
receives. The reader and the guard read it with one function (``core.appositive``). A name
that opens a clause of its own ("..., Ada needs it") or a sentence is read as before."""

from __future__ import annotations

import asyncio

import pytest

from assistantx.core.task_spec import BaseInstruction, Part
from assistantx.evaluation.dataset.generate import generate, verify_tasks
from assistantx.runtime.recipients import _in_roles
from helpers.cover_staff_room import staff_room
from helpers.reading import frame_reader

_frame = frame_reader(staff_room, "tess")


@pytest.mark.parametrize(
    "text",
    [
        "print off my lesson plan for the cover teacher, Ms Okafor",
        "print out my worksheet for our new cover teacher, Ada Okafor, thanks",
        "print my worksheet for the cover teacher, Ada",
        "could you print off my worksheet and take it to the head of year, Ms Okafor please",
    ],
)
def test_the_name_in_apposition_receives(text: str) -> None:
    frame = _frame(text)
    assert [t.recipient for t in frame.tasks] or frame.question, frame
    if frame.tasks:
        assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "ada")], frame
    else:  # "Shall I print your file for Ada Okafor?"
        assert frame.question is not None and "Ada Okafor" in frame.question, frame
    assert _in_roles(staff_room(), text, "tess") == {"ada"}


@pytest.mark.parametrize(
    "text",
    [
        "take my worksheet to the print room, Ada will pick it up",
        "print my worksheet for the meeting. Ada will collect it",
    ],
)
def test_a_name_of_a_clause_of_its_own_is_no_apposition(text: str) -> None:
    assert _in_roles(staff_room(), text, "tess") == frozenset()


def test_a_clause_of_its_own_that_says_who_needs_it_names_them() -> None:
    """No apposition, but a thing taken to a room and one colleague said to need it: she is
    whom it goes to there (``room_receiver``, test_room_receiver.py)."""
    text = "take my worksheet to the print room, Ada needs it"
    assert _in_roles(staff_room(), text, "tess") == {"ada"}


def test_the_optimal_policy_delivers_to_the_person_in_apposition() -> None:
    base = BaseInstruction(
        id="s01",
        requester="tess",
        text="print off my lesson plan for the cover teacher, Ms Okafor",
        parts=[Part(kind="print", to="ada")],
    )
    tasks = generate(staff_room(), [base], verify=False)
    assert tasks
    asyncio.run(verify_tasks(staff_room(), tasks))  # raises where the oracle fails
