"""A later clause that opens with a present participle and no subject is the speaker's own
doing, said as why (class 93d-1, ``screen.participle_clause``): "could I borrow Will's
calculator this afternoon? doing a survey on the high street" borrows the calculator (asked of
its owner) instead of being declined as an errand outside the office. An errand told to the
robot ("go to the high street and ...") and a participle opening the message are read as
before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.participle_clause import own_participle
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader, parser_for

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


@pytest.mark.parametrize(
    ("office", "text", "item", "owner"),
    [
        (
            "harbour",
            "could I borrow will's calculator this afternoon? doing a survey on the high street",
            "calculator",
            "will",
        ),
        (
            "default",
            "could I borrow Wang's stapler today? doing flyers on the high street",
            "stapler",
            "wang",
        ),
        # variants of our own: other verbs, places and punctuation
        (
            "harbour",
            "could I borrow will's calculator, going to the post office after lunch",
            "calculator",
            "will",
        ),
        (
            "harbour",
            "can I borrow will's calculator? printing flyers in town later",
            "calculator",
            "will",
        ),
        (
            "default",
            "could I borrow Wang's stapler? meeting a client at the bank later",
            "stapler",
            "wang",
        ),
        ("default", "can I borrow Wang's book? reading on the train later", "book", "wang"),
    ],
)
def test_a_participle_reason_keeps_the_inside_borrowing(
    office: str, text: str, item: str, owner: str
) -> None:
    frame = _read(office, text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", item, owner)], frame


@pytest.mark.parametrize(
    ("office", "text"),
    [
        ("default", "go to the high street and buy me a sandwich"),
        ("harbour", "go to the high street and buy me a sandwich"),
        # the participle opens the message: nothing before it is asked, read as said
        ("default", "going to the post office, can you get me stamps"),
        ("harbour", "doing a survey on the high street"),
    ],
)
def test_an_errand_outside_is_still_declined(office: str, text: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], frame
    assert frame.decline is not None and "outside the office" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "restored"),
    [
        ("could I borrow it? doing a survey on the high street", True),
        ("can I have it, going to the bank later", True),
        # an office thing's name that opens with "-ing" is no doing of the speaker's
        ("can you bring me paper, charging cable too", False),
        # asked, not told; and a message's own first clause, as said
        ("could I borrow it? printing it?", False),
        ("doing a survey on the high street", False),
        # a plain form in "-ing" is no participle ("bring")
        ("please, bring me one", False),
    ],
)
def test_which_clauses_get_their_subject_back(text: str, restored: bool) -> None:
    read = parser_for(default_office).screen.terms.lex.read
    said, found = own_participle(text, read)
    assert ("I'm" in said) is restored and bool(found) is restored, said
