"""A possessive opening a later clause with its article dropped ("..., visitor's pen just ran
out") names someone outside the office when its word is a lower-case common noun that is no
colleague's name or alias: the reason is context, never a name to ask about (fix121a class 1).
Colleagues named the same way, in lower case or not, are read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_lin = frame_reader(default_office, "lin")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text", "item", "who"),
    [
        (_lin, "need a pen in the meeting room, visitor's pen just ran out", "pen", "lin"),
        (_lin, "bring me a stapler, client's one broke", "stapler", "lin"),
        (_lin, "bring me a pen, student's pen just died", "pen", "lin"),
        (_lin, "could you get me some scissors, plumber's scissors just broke", "scissors", "lin"),
        (_may, "bring me a calculator, trainee's calculator just died", "calculator", "may"),
        (_may, "bring me a ruler, passenger's ruler snapped", "ruler", "may"),
        (_may, "bring me a ruler, trainee's ruler just snapped", "ruler", "may"),
    ],
)
def test_an_outsider_opening_the_reason_leaves_the_need_alone(
    read: ReadFrame, text: str, item: str, who: str
) -> None:
    frame = read(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, who)
    ], frame


@pytest.mark.parametrize(
    ("read", "text", "item", "owner", "who"),
    [
        (_lin, "bring me wang's stapler", "stapler", "wang", "lin"),
        (_lin, "bring me a pen, Wang's ran out", "pen", None, "lin"),
        (_lin, "bring me a pen, wang's pen just ran out", "pen", None, "lin"),
        (_may, "bring me a ruler, mark's ruler just snapped", "ruler", None, "may"),
        (_may, "bring me mark's ruler", "ruler", "mark", "may"),
    ],
)
def test_a_colleague_named_the_same_way_is_read_as_before(
    read: ReadFrame, text: str, item: str, owner: str | None, who: str
) -> None:
    frame = read(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, who)
    ], frame


def test_a_determiner_owner_is_still_the_existing_reading() -> None:
    # the article-bearing form (reading/outsider_owner) is unchanged by the clause rule
    frame = _lin("bring me a pen, the visitor's pen just ran out")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "pen", None, "lin")
    ], frame
