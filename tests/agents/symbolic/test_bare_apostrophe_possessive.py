"""A possessive written with a bare apostrophe after a final s ("could u grab miles' pressure
guage for me", "can I borrow James' stapler", blind round 50's class; its own sentences were
never read) is the named colleague's, whatever the case: the tokenizer's word pattern left the
trailing apostrophe out, so "miles'" was a plain word (anyone's gauge, or a doubt between
Miles and the word). "miles" as a distance stays a word; a quoted 'word' is no possessive."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.tokens import tokenize
from helpers.reading import frame_reader
from helpers.survey_hut import survey_hut

_frame = frame_reader(survey_hut, "pim")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("could u grab miles' pressure guage for me, need it till 4", "gauge", "miles"),
        ("could you grab Miles' pressure gauge for me", "gauge", "miles"),
        ("grab miles' gauge pls", "gauge", "miles"),
        ("can I borrow miles' clipboard", "clipboard", "miles"),
        ("need miles’ clipbaord for a sec", "clipboard", "miles"),
        # near-misses read as before
        ("could u grab miles's pressure gauge for me", "gauge", "miles"),
        ("the yard is miles away, bring me a clipboard", "clipboard", None),
    ],
)
def test_a_bare_apostrophe_possessive_names_the_owner(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "pim")
    ], frame


def test_miles_as_a_distance_stays_a_word() -> None:
    frame = _frame("it's miles away")
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "possessive"),
    [
        ("James' stapler", [True, False]),
        ("james' stapler", [True, False]),
        ("the 'boss' stapler", [False, False, False]),
        ("it is miles away", [False, False, False, False]),
        ("ask James's team", [False, True, False]),
    ],
)
def test_the_tokenizer_keeps_a_bare_apostrophe(text: str, possessive: list[bool]) -> None:
    assert [t.possessive for t in tokenize(text)] == possessive
