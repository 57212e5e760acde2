"""A noun's "'s" before a participle or a preposition is "has"/"is", never a possessive of
the next noun (fix121a class 2): "the visitor's gone home" is a statement, "Wang's gone to
lunch with the scissors" makes no lunch Wang's. A possessive before a noun, before a
hyphened compound, or after a preposition stays one."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.contracted_has_is import spelled_has_is
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_lin = frame_reader(default_office, "lin")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_lin, "never mind the pen, the visitor's gone home"),
        (_lin, "never mind the stapler, the client's left already"),
        (_may, "never mind the calculator, the trainee's gone home"),
        (_may, "forget the ruler, the courier's been and gone"),
    ],
)
def test_a_withdrawal_with_a_subjects_has_is_words_only(read: ReadFrame, text: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "dropped" in frame.decline, frame


@pytest.mark.parametrize(
    ("read", "text", "item", "owner", "who"),
    [
        (
            _lin,
            "Wang's gone to lunch with the scissors, can you get me Zhang's?",
            "scissors",
            "zhang",
            "lin",
        ),
        (
            _lin,
            "Zhang's at lunch with the stapler, can you get me Wang's?",
            "stapler",
            "wang",
            "lin",
        ),
        (_lin, "Wang's off today, can you get me Zhang's stapler?", "stapler", "zhang", "lin"),
        (_may, "Mark's gone to lunch with the ruler, can you get me Joy's?", "ruler", "joy", "may"),
        (
            _may,
            "Will's out today, could you bring me Dawn's calculator?",
            "calculator",
            "dawn",
            "may",
        ),
    ],
)
def test_a_colleague_away_is_context_for_the_request(
    read: ReadFrame, text: str, item: str, owner: str, who: str
) -> None:
    frame = read(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, who)
    ], frame


@pytest.mark.parametrize(
    ("text", "spelled"),
    [
        ("the visitor's gone home", "the visitor is gone home"),
        ("Zhang's at lunch", "Zhang is at lunch"),
        ("Dad says his son's lost his tie", "Dad says his son has lost his tie"),
        ("the client's left already", "the client has left already"),
        # a noun described before it (blind round 212: "My phone cable's at home. Could I
        # borrow Dang's?" asked where the speaker's own cable was)
        ("My phone cable's at home", "My phone cable is at home"),
        ("my old laptop cable's gone", "my old laptop cable is gone"),
        ("the stapler on Wang's in the drawer", "the stapler on Wang's in the drawer"),
        # possessives: before a noun, a hyphened compound, after a preposition
        ("bring me Wang's gone-off milk", "bring me Wang's gone-off milk"),
        ("bring me Wang's lost stapler", "bring me Wang's lost stapler"),
        ("put it on Wang's in the morning", "put it on Wang's in the morning"),
        ("Wang's lunch is in the fridge", "Wang's lunch is in the fridge"),
        ("let's go out", "let's go out"),
    ],
)
def test_what_is_spelled_out(text: str, spelled: str) -> None:
    assert spelled_has_is(text) == spelled


@pytest.mark.parametrize(
    ("read", "text", "item", "owner", "who"),
    [
        (_lin, "bring me Wang's stapler", "stapler", "wang", "lin"),
        (_lin, "My phone cable's at home. Could I borrow Dang's?", "data_cable", "dang", "lin"),
        (_lin, "put the stapler on Wang's desk", "stapler", None, "wang"),
        (_may, "bring me Joy's ruler", "ruler", "joy", "may"),
    ],
)
def test_a_possessive_before_a_noun_is_read_as_before(
    read: ReadFrame, text: str, item: str, owner: str | None, who: str
) -> None:
    frame = read(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, who)
    ], frame


def test_wangs_lunch_is_still_wangs() -> None:
    # "Wang's lunch is in the fridge": a possessive before a noun, asked about as before
    frame = _lin("Wang's lunch is in the fridge, bring it to him")
    assert frame.tasks == [] and frame.question is not None and "lunch" in frame.question, frame


@pytest.mark.parametrize("text", ["Wang's gone to lunch", "Wang's gone home", "Zhang's at lunch"])
def test_a_colleague_gone_is_still_away(text: str) -> None:
    frame = _lin(text)
    assert frame.tasks == [] and frame.decline is not None and "is away" in frame.decline, frame
