"""A reason clause about an outsider told beside a request is context, not a colleague to
find nor news that the thing is had (``reading.taken_from_speaker``): "I need a pen because
the client's lost his" is a pen for the speaker (its "his" is the client's); "bring me a pen,
the intern borrowed mine" was read as "what was asked for is had already" and the request was
dropped. The speaker's own taking or being given one still withdraws the request, and a
colleague's possessive with "he said it's fine" is still theirs."""

from __future__ import annotations

from typing import Any

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "may")


def _tasks(frame: Any) -> list[tuple[str, str, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need a pen because the client's lost his", "pen"),
        ("bring me a stapler, the visitor broke hers", "stapler"),
        ("bring me a pen, the intern borrowed mine", "pen"),
        ("I need a pen, the new intern borrowed mine and lost it", "pen"),
        ("can you get me a stapler, the visitor took mine", "stapler"),
        ("could I have some scissors, a courier nicked my pair", "scissors"),
    ],
)
def test_default_office_reason_about_an_outsider_is_context(text: str, item: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("transfer", item, None, "lin")], frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need a ruler because the client's lost his", "ruler"),
        ("I need a calculator, the auditor borrowed mine", "calculator"),
        ("get me a charger, the courier took mine", "charger"),
        ("can you bring me a calculator, the auditor broke hers", "calculator"),
    ],
)
def test_harbour_reason_about_an_outsider_is_context(text: str, item: str) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("transfer", item, None, "may")], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me a pen, I borrowed one already",
        "bring me a pen, actually Wang already brought me one",
        "bring me a pen, I already took mine back",
    ],
)
def test_the_speaker_having_one_still_withdraws(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.decline is not None, frame


def test_a_colleagues_own_thing_with_their_word_is_unchanged() -> None:
    frame = _default("bring me Wang's stapler, he said it's fine")
    assert _tasks(frame) == [("transfer", "stapler", "wang", "lin")], frame


@pytest.mark.parametrize(
    "text",
    [
        "would you bring me a pen? I'm dying to know who took mine",
        "bring me a pen, I wonder who took mine",
    ],
)
def test_a_wondered_taker_is_why_the_speaker_asks(text: str) -> None:
    """ "I'm dying to know who took mine": the taking's subject is "who", not the speaker
    before it; before, the request was dropped as had already (noticed by fix169b)."""
    frame = _default(text)
    assert [(kind, item) for kind, item, _, _ in _tasks(frame)] == [("transfer", "pen")], frame
