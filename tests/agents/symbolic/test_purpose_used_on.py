"""Fixer fix59h class 2: a purpose phrase names the thing by its verb; the object after the
verb ("something to wipe up *the tea* I just knocked over") is what the thing is used on, never
a thing asked for (``screen.purpose_object.used_on``). Before, the default office (no tea;
wipes for "wipe" and "clean") declined "I can't get you any tea", and "something to mop up the
coffee I spilled" made a coffee. Unchanged: a thing asked beside the purpose ("need some tea
and something to wipe with": the tea is declined), a purpose with no object."""

from __future__ import annotations

import pytest
from _offices import parser

from assistantx.agents.symbolic.reading.screen.purpose_object import used_on


@pytest.mark.parametrize(
    "text",
    [
        "need something to wipe up the tea i just knocked over",
        "need something to wipe the tea off my desk",
        "anything to clean the water off my desk?",
        "need something to clean up the coffee i spilled",
    ],
)
def test_what_a_purpose_is_used_on_is_not_asked_for(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "wipes", "lee")], (
        frame
    )


def test_an_undeclared_purposes_object_is_never_made() -> None:
    frame = parser("default").parse("need something to mop up the coffee i spilled", "lee")
    assert frame.tasks == [] and frame.decline is None, frame
    assert frame.question is not None and "coffee" not in frame.question, frame


@pytest.mark.parametrize(
    ("text", "used"),
    [
        ("need something to wipe up the tea i just knocked over", ["the", "tea"]),
        ("anything to clean the water off my desk", ["the", "water"]),
        ("something i can cut ribbon with", ["ribbon"]),
        ("need some tea and something to wipe with", None),
        ("need something to drink", None),
        ("need something for the tea", None),
        ("something to open its lid", ["its", "lid"]),
        ("i need something to see its under the mark", None),
    ],
)
def test_used_on(text: str, used: list[str] | None) -> None:
    words = text.split()
    found = used_on(words)
    assert (words[found.start : found.stop] if found else None) == used


# -- must not change ---------------------------------------------------------------------


def test_a_thing_asked_beside_a_purpose_is_still_declined() -> None:
    frame = parser("default").parse("need some tea and something to wipe with", "lee")
    assert frame.decline is not None and "tea" in frame.decline, frame


def test_a_purpose_with_no_object_is_read_as_before() -> None:
    frame = parser("default").parse("need something to wipe with", "lee")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "wipes")], frame
