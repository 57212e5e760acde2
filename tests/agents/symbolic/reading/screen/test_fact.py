"""Fact: a person away, here or somewhere; an item's condition; the requester's own item out
of use. Each is a hint for the plan."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.fact import fact
from reading.screen._judge import Judge


@pytest.mark.parametrize(
    ("text", "hint"),
    [
        ("Wang is away", ("availability", "wang", "away", None)),
        ("Zhang is back", ("availability", "zhang", "here", None)),
        ("Zhang is in the meeting room", ("location", "zhang", "meeting_room", None)),
        ("Zhang's stapler is broken", ("condition", "zhang", "broken", "stapler")),
        # the requester's own item out of use: they want someone else's
        ("I can't find my stapler", ("condition", "lee", "missing", "stapler")),
    ],
)
def test_a_fact_is_a_hint(judged: Judge, text: str, hint: tuple[str, str, str, str | None]) -> None:
    found = judged(fact, text, "lee")
    assert found is not None and found.hint is not None
    h = found.hint
    assert (h.kind, h.person, h.value, h.item_type) == hint


@pytest.mark.parametrize(
    "text",
    [
        "bring me Wang's stapler",
        "Wang needs a stapler",
        "Wang is away from his desk until the meeting after lunch",  # more than a state
    ],
)
def test_what_is_no_fact(judged: Judge, text: str) -> None:
    assert judged(fact, text, "lee") is None
