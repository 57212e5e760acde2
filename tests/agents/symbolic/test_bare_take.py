"""A bare "take the X", said by someone with no X of their own, says neither whose X nor who
gets it (fix154b, class 6): the requester is asked both, never a colleague's thing carried
off to them; their answer is read into the request's own words (``reading.bare_take``)."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

_ASKS = "Whose {} should I take, and who should get it?"


@pytest.mark.parametrize(
    ("office", "requester", "text", "name"),
    [
        # the class's analogues (Zhou owns no stapler, Wang Fang and others do)
        ("default", "zhou", "take the stapler", "stapler"),
        ("default", "zhou", "take the scissors", "scissors"),
        ("harbour", "may", "take the ruler pls", "ruler"),
        # variants: other words, other things, courtesy around the imperative
        ("default", "zhou", "please take the shears", "scissors"),
        ("default", "wang", "could you take the book please", "book"),
        ("harbour", "rose", "take the calculator", "calculator"),
    ],
)
def test_a_bare_take_asks_whose_and_for_whom(
    office: str, requester: str, text: str, name: str
) -> None:
    frame = parser(office).parse(text, requester)
    assert frame.tasks == [] and frame.question == _ASKS.format(name), frame


@pytest.mark.parametrize(
    ("answer", "expected"),
    [
        ("It's Zhang Wei's stapler, for me.", [("transfer", "stapler", "zhang", "zhou")]),
        ("Wang's, to Zhang please", [("transfer", "stapler", "wang", "zhang")]),
    ],
)
def test_the_answer_says_whose_and_who_gets_it(
    answer: str, expected: list[tuple[str, str, str, str]]
) -> None:
    frame = parser("default").parse_with_answers("take the stapler", "zhou", [answer])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == expected, frame


# -- must not change: whose or who gets it said, a borrowing, one's own, a supply -----------
@pytest.mark.parametrize(
    ("office", "requester", "text", "expected"),
    [
        ("default", "zhou", "can I take Wang's stapler", [("transfer", "stapler", "wang", "zhou")]),
        ("default", "zhou", "take the stapler for me", [("transfer", "stapler", None, "zhou")]),
        ("default", "zhou", "bring me the stapler", [("transfer", "stapler", None, "zhou")]),
        ("harbour", "may", "take the tape", [("transfer", "tape", None, "may")]),
    ],
)
def test_whose_or_whom_said_is_not_asked(
    office: str, requester: str, text: str, expected: list[tuple[str, str | None, str, str]]
) -> None:
    assert tasks_of(office, text, requester) == expected


def test_taken_to_a_colleague_asks_whose_as_before() -> None:
    frame = parser("default").parse("take the stapler to Wang", "zhou")
    assert (frame.question or "").startswith("Several colleagues have a stapler"), frame
