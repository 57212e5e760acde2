"""Emoji and other pictographs are tone, never content (``reading.pictographs``): the same
words read the same with a face, a gesture or a composed emoji after or before them (blind
round 103: "I've got 60 envelopes to label and no marker 😩" was taken as a statement, the
same words without the face as the want they are)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.pictographs import without_pictographs
from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "kept"),
    [
        ("no marker 😩", "no marker"),
        ("a pen 🙏🏽 thx", "a pen, thx"),  # a skin-tone modifier goes with its emoji
        ("👨‍💻 print my file", "print my file"),  # joined by zero-width joiners
        ("ok ❤️", "ok"),  # a variation selector
        ("Zoë's pen", "Zoë's pen"),  # letters of any script stay
        ("£5 for a coffee?", "£5 for a coffee?"),  # a currency sign is content
        ("print 2 copies", "print 2 copies"),
    ],
)
def test_what_is_taken_out(text: str, kept: str) -> None:
    assert without_pictographs(text) == kept


def _tasks(text: str) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in _default(text).tasks]


@pytest.mark.parametrize(
    "text",
    [
        "I've got 40 forms to sign and no pen 😩",
        "I've got 40 forms to sign and no pen",
        "😩 I've got 40 forms to sign and no pen",
    ],
)
def test_a_want_reads_the_same_with_a_face(text: str) -> None:
    assert _tasks(text) == [("transfer", "pen", "lee")]


def test_a_request_reads_the_same_with_a_gesture() -> None:
    assert _tasks("can you bring me a pen 🙏🏽 thx") == [("transfer", "pen", "lee")]


def test_a_thank_you_with_a_thumb_moves_nothing() -> None:
    frame = _default("👍 thanks for the pen")
    assert frame.tasks == [] and frame.question is None, frame
