"""A thing poured or thrown away ("tip the rest of Wang's coffee down the drain", "chuck
Zhang's old cable out", fix186a class 2): "down the drain" (sink, loo ...) whatever the verb,
"into the sink" or "away"/"out" with a verb of discarding and no one the thing goes to, is
disposal (``screen.destructive``): declined, never a fetch of the colleague's thing nor the
office's coffee made. A verb only of tossing a thing somewhere ("tip", "hurl", "stash": none
of the office's work, task words or giving verbs) on a colleague's thing said to go nowhere is
work nothing here does (``screen.unknown_work``): declined, never a fetch. Making, giving,
taking out, putting and a tossing verb with a receiver or a place read as before."""

from __future__ import annotations

import pytest
from _offices import parser, understood_tasks


@pytest.mark.parametrize(
    "text",
    [
        "tip the rest of Wang's coffee down the drain, it's gone cold",
        "pour Wang's coffee down the sink",
        "pour away Wang's coffee",
        "pour Wang's coffee away",
        "empty Wang's water into the sink",
        "chuck Zhang's old cable out, it's frayed",
        "tip out Zhang's cable",
        "chuck Zhang's old cable in the skip, it's frayed",  # as before
    ],
)
def test_disposal_is_declined(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert not frame.tasks, frame
    assert frame.decline is not None and "won't" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "verb"),
    [
        ("tip Zhang's cable", "tip"),
        ("hurl Zhang's stapler", "hurl"),
        ("stash Wang's stapler", "stash"),
        ("chuck Zhang's cable", "chuck"),
    ],
)
def test_a_tossing_verb_going_nowhere_is_no_fetch(text: str, verb: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert not frame.tasks, frame
    assert frame.decline is not None and f"can't {verb}" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("chuck me Zhang's cable", [("transfer", "data_cable", "zhang", "lee")]),
        ("chuck Zhang's cable over", [("transfer", "data_cable", "zhang", "lee")]),
        ("chuck Zhang's cable my way", [("transfer", "data_cable", "zhang", "lee")]),
        ("chuck my lunch", [("transfer", "lunch", "lee", "lee")]),
        ("bung Zhang's lunch in the microwave", [("heat", "lunch", "zhang", "lee")]),
        ("pour me a coffee", [("produce", "coffee", None, "lee")]),
        ("pour Wang a coffee", [("produce", "coffee", None, "wang")]),
        ("pour out a coffee for Wang", [("produce", "coffee", None, "wang")]),
        ("chuck me Wang's stapler", [("transfer", "stapler", "wang", "lee")]),
        ("take Wang's lunch out of the fridge", [("transfer", "lunch", "wang", "lee")]),
        ("get the paper out for me", [("transfer", "paper", None, "lee")]),
        ("print out my report", [("print", "file", "lee", "lee")]),
    ],
)
def test_other_verbs_read_as_before(
    text: str, tasks: list[tuple[str, str, str | None, str]]
) -> None:
    assert understood_tasks("default", "lee", text) == tasks
