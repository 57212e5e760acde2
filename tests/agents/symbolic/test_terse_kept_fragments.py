"""Terse fragments that name a personal item and, set off on its own, the facility where the
requester's own item of that type is kept ("keys. key safe. now pls", "lunch - fridge - asap",
blind round 50's class; its own sentences were never read) ask for the requester's own; the
reader asked whose. A dash set off by spaces is a pause, as a comma is ("keys - key safe":
"keys" was read as a word before the facility's name). A requester who keeps none there is
still asked whose."""

from __future__ import annotations

import pytest
from _offices import parser

from helpers.reading import frame_reader
from helpers.survey_hut import survey_hut

_frame = frame_reader(survey_hut, "okafor")


@pytest.mark.parametrize(
    "text",
    [
        "keys. key safe. now pls",
        "van keys - key safe - asap",
        "keys - key safe - now pls",
        "my keys, key safe, pls",
        "key safe. keys. pls",
        "keys — key safe — asap",
    ],
)
def test_a_fragment_naming_where_the_requesters_own_is_kept(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "van_keys", "okafor", "okafor")
    ], frame


@pytest.mark.parametrize(
    "text", ["lunch. fridge. pls", "lunch, fridge, now pls", "my lunch - fridge - asap"]
)
def test_the_default_offices_lunch_in_the_fridge(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "lunch", "lee", "lee")
    ], frame


def test_one_who_keeps_none_there_is_asked_whose() -> None:
    frame = _frame("keys. key safe. now pls", "pim")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Whose van keys" in frame.question, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [("van keys pls", None), ("bring me a hi-vis vest pls", "vest")],
)
def test_near_misses_read_as_before(text: str, item: str | None) -> None:
    frame = _frame(text)
    if item is None:
        assert frame.tasks == [] and frame.question is not None, frame
    else:
        assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", item)], frame
