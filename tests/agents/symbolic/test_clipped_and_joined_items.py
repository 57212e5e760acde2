"""An item named by an English clip of a word of its name ("pic" for the picture, "spec" for
the specification, "mic" for the microphone) or by its compound name written open, hyphenated
or closed ("walkie talkie", "walkie-talkie", "walkietalkie", "headtorch") is that item (blind
rounds 59-64's class: the clip was an unknown thing, and "walkie" of the compound was typo-
corrected to "talkie"). Clips come from english.yaml's ``clipped_words``, never an office's
table: a clip that starts a word of two things ("mic" beside a microscope) names neither and
is asked about, and a real word that merely starts a name ("car" of a cartridge, with a car
park) is never read as the item."""

from __future__ import annotations

import pytest

from helpers.media_cupboard import media_cupboard, sound_cupboard
from helpers.reading import frame_reader

_frame = frame_reader(media_cupboard, "pat")
_sound = frame_reader(sound_cupboard, "pat")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("bring me Remi's pic", "picture", "remi"),
        ("could you grab Remi's pics for me", "picture", "remi"),
        ("bring me Sasha's spec", "specification", "sasha"),
        ("fetch Sasha's specs please", "specification", "sasha"),
        ("bring me Remi's walkie talkie", "walkie_talkie", "remi"),
        ("bring me Remi's walkie-talkie", "walkie_talkie", "remi"),
        ("bring me Remi's walkietalkie", "walkie_talkie", "remi"),
        ("bring me Ivo's headtorch", "head_torch", "ivo"),
        ("bring me Ivo's head-torch", "head_torch", "ivo"),
    ],
)
def test_a_clip_or_a_joined_compound_names_the_item(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, owner, "pat")]


@pytest.mark.parametrize("text", ["bring me Remi's mic", "can you get me Remi's mics"])
def test_a_clip_of_one_item_only_names_it(text: str) -> None:
    frame = _sound(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.item, t.owner) for t in frame.tasks] == [("microphone", "remi")]


@pytest.mark.parametrize(
    "text",
    [
        "bring me Remi's mic",  # a microphone and a microscope: which?
        "bring me Sasha's car",  # "car" of the car park, never the cartridge
        "bring me Remi's walkie",
    ],
)
def test_a_clip_that_is_not_one_items_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.question is not None or frame.decline is not None, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("bring me Remi's microphone", "microphone"),
        ("bring me Sasha's microscope", "microscope"),
        ("bring me Sasha's cartridge", "cartridge"),
        ("bring me the fridge", "fridge"),
    ],
)
def test_full_names_read_as_before(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [t.item for t in frame.tasks] == [item]
