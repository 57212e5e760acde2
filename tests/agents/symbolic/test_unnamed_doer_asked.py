"""A doer said without naming anyone: "can you get someone to sign my contract" (fixer fix189c;
the round's own sentences were never read).

"get someone / somebody / anyone to <verb> my X" names nobody to do the work; "someone" there
is the doer of the verb after it, not whom a thing is handed to. It was read as a recipient
outside the office ("I hand things only to people of this office, and I don't know who someone
is"). Who should do it is asked instead (or, where the robot's office does the work, done);
the outsider reading stays for a thing handed to "someone" and for a doer who is described
("the visitor")."""

from __future__ import annotations

import pytest
from _offices import parser

from helpers.reading import answered_reader

_answered = answered_reader(lambda: parser("default").office, "lee")


def _frame(text: str):  # type: ignore[no-untyped-def]
    return parser("default").parse(text, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "can you get someone to sign my contract",
        "get somebody to sign my contract",
        "could you get anyone to sign my contract",
        "could you get anybody to approve my contract",
        "get somebody to check my report",
    ],
)
def test_an_unnamed_doer_is_asked_who(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and not frame.tasks, frame
    assert frame.question is not None and frame.question.startswith("Who should "), frame
    assert "outside" not in frame.explain() and "I don't know who" not in frame.question


@pytest.mark.parametrize(
    "text", ["can you get someone to stamp my contract", "get somebody to stamp my form"]
)
def test_an_unnamed_stamper_is_whoever_has_a_seal(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.owner, t.actor) for t in frame.tasks] == [("seal", "lee", None)], frame


def test_the_answer_names_the_signer() -> None:
    frame = _answered("can you get someone to sign my contract", ["Manager Mao"])
    assert [(t.kind, t.owner, t.actor) for t in frame.tasks] == [("sign", "lee", "mao")], frame


def test_the_unnamed_doer_of_a_service_is_the_robot() -> None:
    frame = _frame("can you get someone to print my report")
    assert [(t.kind, t.item) for t in frame.tasks] == [("print", "file")], frame


# -- must not change --------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "give my contract to someone",  # handed to nobody of the office
        "get someone a coffee",  # "someone" the one it goes to
        "get the visitor to sign my contract",  # a described doer, nobody of the office
    ],
)
def test_someone_who_gets_a_thing_is_still_an_outsider(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks and "outside the office" in frame.explain(), frame


def test_a_named_doer_still_signs() -> None:
    frame = _frame("can you get Manager Mao to sign my contract")
    assert [(t.kind, t.owner, t.actor) for t in frame.tasks] == [("sign", "lee", "mao")], frame
