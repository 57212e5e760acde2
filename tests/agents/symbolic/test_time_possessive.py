"""A time's possessive ("this week's report", "today's rota", "last month's report") says
when, not whose: no one called 'week' is asked about, and the paper stays the speaker's.
A real colleague's possessive still names the owner."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("print this week's report and take it to Wang", "wang"),
        ("print last month's report", "lee"),
        ("please print today's rota for me", "lee"),
        ("print next year's report and give it to Zhang", "zhang"),
        ("could you print this morning's minutes", "lee"),
        ("print last quarter's report and bring it to Chen", "chen"),
    ],
)
def test_a_times_possessive_is_nobody(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("print", "lee", recipient)], (
        frame
    )


@pytest.mark.parametrize(
    "text",
    ["bring me Wang's stapler", "could you get me Wang's stapler"],
)
def test_a_colleagues_possessive_still_names_the_owner(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.owner) for t in frame.tasks] == [("transfer", "wang")], frame


def test_an_unknown_name_is_still_asked_about() -> None:
    frame = _frame("bring me Kowalski's stapler")
    assert frame.question is not None and "Kowalski" in frame.question, frame
