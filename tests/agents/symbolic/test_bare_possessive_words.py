"""A possessive written without its apostrophe where the name plus "s" is also an English
word ("can i borrow hunters pad", Hunter's): read as the possessive where the colleague keeps
that item (``reading.bare_possessives``); a colleague who keeps no such item is asked about
(theirs, or anyone's?); a name not right before an item keeps its old reading."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.sound_desk import sound_desk

_frame = frame_reader(sound_desk, "ingrid")


def _tasks(text: str) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text).tasks]


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("can i borrow hunters pad", "pad", "hunter"),
        ("bring me Hunters pad pls", "pad", "hunter"),
        ("could i borrow robins pad for a bit", "pad", "robin"),
        ("can i borrow cliffs headset", "headset", "cliff"),
    ],
)
def test_a_name_word_and_s_before_an_item_they_keep_is_theirs(
    text: str, item: str, owner: str
) -> None:
    assert _tasks(text) == [("transfer", item, owner, "ingrid")]


def test_a_colleague_who_keeps_no_such_item_is_asked_about() -> None:
    # Cliff keeps no pad: Cliff's (which he lacks) or any pad? Asked, never guessed
    frame = _frame("can i borrow cliffs pad")
    assert frame.question is not None and ", or any pad?" in frame.question, frame
    assert all(t.owner is None for t in frame.tasks), frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("take my headset to hunter", [("transfer", "headset", "ingrid", "hunter")]),
        ("can i borrow hunter's pad", [("transfer", "pad", "hunter", "ingrid")]),
    ],
)
def test_a_name_before_no_item_or_with_its_apostrophe_reads_as_before(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _tasks(text) == expected
