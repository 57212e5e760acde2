"""A clause of time with a subject of its own ("before I sign off tonight", "before Wang
prints the contracts") says when, not what to do: its verbs are no requests. Before, "sign"
in "my report needs printing before I sign off tonight, can you sort it?" was read as a
signing task ("Who should sign your document?"), and "prints" in "bring me a stapler
before Wang prints the contracts" left the stapler's errand unread. A time phrase without a
subject ("before lunch") and a clause whose subject is the robot ("when you are at the
printer") are no such clause."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "my report needs printing before I sign off tonight, can you sort it?",
            [("print", "file", "lin")],
        ),
        ("bring me a stapler before Wang prints the contracts", [("transfer", "stapler", "lin")]),
        ("bring me a coffee when I get back from the meeting", [("produce", "coffee", "lin")]),
        ("as soon as I am back, get me a coffee", [("produce", "coffee", "lin")]),
        (
            "print my report before the client arrives and take it to Wang",
            [("print", "file", "wang")],
        ),
        (
            "once Zhang has signed it, take my contract to Wang",
            [("transfer", "document", "wang")],
        ),
    ],
)
def test_a_time_clause_with_its_own_subject_asks_nothing(
    text: str, tasks: list[tuple[str, str, str]]
) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == tasks


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "my report needs printing before I sign off tonight, can you sort it?",
            [("print", "file", "will")],
        ),
        ("bring me a notepad before Rose signs the lease", [("produce", "notepad", "will")]),
    ],
)
def test_the_same_on_harbour(text: str, tasks: list[tuple[str, str, str]]) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == tasks


def test_a_time_phrase_without_a_subject_keeps_its_request() -> None:
    """Neighbour: "before lunch" is a time phrase; Wang's signing is asked for."""
    frame = _default("before lunch, get Wang to sign my contract")
    assert [(t.kind, t.item, t.actor) for t in frame.tasks] == [("sign", "document", "wang")]


def test_the_robot_as_the_clauses_subject_is_no_context_clause() -> None:
    """Neighbour: "when you are at the printer" is the robot's own errand; the printout is
    still brought."""
    frame = _default("when you are at the printer, bring me my printout")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "lin")]


@pytest.mark.parametrize(
    "text",
    [
        # blind round 136 ("could you sit with bed 7 for ten minutes while I grab a coffee?")
        # made the requester a drink: a wrong physical action; the coffee is theirs to grab
        "could you sit with Wang for ten minutes while I grab a coffee?",
        "could you watch my desk while I grab a coffee?",
        "keep an eye on my desk whilst I grab a coffee",
    ],
)
def test_the_speakers_own_errand_meanwhile_is_no_request(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [], frame


def test_a_request_with_the_speakers_errand_meanwhile_keeps_its_request() -> None:
    frame = _default("could you print my report while I grab a coffee?")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "lin")]


def test_while_the_robot_is_somewhere_it_is_still_asked() -> None:
    # must not change: "while you're at the printer" is the robot's own errand
    frame = _default("while you're at the printer, grab me a coffee")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "coffee", "lin")]
