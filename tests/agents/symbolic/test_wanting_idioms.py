"""Idioms of wanting ("I'd murder a cappuccino", "I could kill for one", "I'm dying for a
...", "I could really go for a ...") are the speaker's need of the thing, alone or as the
second part of a message after another request, and an opening count ("Two things:", "A
couple of things -") names nothing (blind rounds 59-64's class: the second part was lost or
read as a statement). The idiom with no thing wanted ("I'd murder whoever ...", "I'm dying to
know ...") moves nothing, and a plain request is read as before."""

from __future__ import annotations

import pytest

from helpers.lamp_works import lamp_works
from helpers.reading import frame_reader

_frame = frame_reader(lamp_works, "odile")
_TORCH = ("transfer", "torch", "odile", "ginger")
_COFFEE = ("produce", "cappuccino", None, "odile")


def _tasks(text: str) -> list[tuple[str, str | None, str | None, str | None]]:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Two things: my torch needs to go to Ginger, and I'd murder a cappuccino.",
        "A couple of things: take my torch to Ginger, and I could kill for a cappuccino",
        "couple of things - my torch needs to go to Ginger and I'm dying for a cappuccino",
        "please take my torch to Ginger. Also I'd kill for a cappuccino!",
        "take my torch to Ginger, and I could really go for a cappuccino",
        "Two quick things: bring my torch to Ginger. I would absolutely murder a cappuccino",
        "take my torch to Ginger, and I'm gagging for a cappuccino",
        "take my torch to Ginger, and I'd give anything for a cappuccino",
        "take my torch to Ginger, and im desperate for a cappuccino",
        "take my torch to Ginger, and I'm craving a cappuccino",
        "take my torch to Ginger, and I really fancy a cappuccino",
    ],
)
def test_an_idiom_of_wanting_after_a_request_is_a_second_request(text: str) -> None:
    assert _tasks(text) == [_TORCH, _COFFEE]


@pytest.mark.parametrize(
    "text",
    [
        "I'd murder a cappuccino",
        "I could kill for a cappuccino right now",
        "I'm dying for a cappuccino",
        "honestly I could really go for a cappuccino",
        "we'd kill for a cappuccino",
    ],
)
def test_an_idiom_of_wanting_alone_is_a_request_for_the_speaker(text: str) -> None:
    assert _tasks(text) == [_COFFEE]


@pytest.mark.parametrize(
    "text",
    [
        "Two things: take my torch to Ginger",
        "A couple of things - my torch needs to go to Ginger",
        "take my torch to Ginger",
    ],
)
def test_an_opening_count_names_nothing(text: str) -> None:
    assert _tasks(text) == [_TORCH]


@pytest.mark.parametrize(
    "text",
    [
        "I'd murder whoever took my torch",
        "I'm dying to know who took my torch",
        "I could kill for some peace and quiet",
        "two things are broken in here",
        "I go for a walk every day",
        "Ginger fancies a cappuccino",
    ],
)
def test_no_thing_wanted_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


@pytest.mark.parametrize(
    "text",
    [
        "I'd murder a cappuccino, and my torch needs to go to Ginger.",
        "I'm dying for a cappuccino and my torch should go to Ginger",
        "I need a cappuccino, and my torch has to go to Ginger",
    ],
)
def test_a_delivery_said_after_the_want_keeps_its_own_recipient(text: str) -> None:
    assert _tasks(text) == [_COFFEE, _TORCH]
