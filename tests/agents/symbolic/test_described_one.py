"""A thing said again by "one" with describing words is another of the thing stated
(screen/described_one.py): "the cup needs washing, bring me a clean one" asked what "a clean"
is; now it asks for a cup, as "bring me a new one" did. Describing words that name a thing of
the office, and a "one" with nothing stated before it, are read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    ("read", "text", "item", "who"),
    [
        (_default, "the cup needs washing, bring me a clean one", "cup", "lee"),
        (_default, "my cup is dirty, bring me a clean one", "cup", "lee"),
        (_harbour, "this ruler is bent, bring me a straight one", "ruler", "rose"),
        (_harbour, "the charger's broken, get me a working one", "charger", "rose"),
        # unchanged: "a new one" was read so before
        (_default, "the cup needs washing, bring me a new one", "cup", "lee"),
    ],
)
def test_a_described_one_is_another_of_the_thing_stated(
    read: ReadFrame, text: str, item: str, who: str
) -> None:
    frame = read(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, who)], frame


def test_a_described_one_with_nothing_stated_is_read_as_before() -> None:
    frame = _default("bring me a clean one")
    assert frame.tasks == [] and frame.decline is not None
    assert "no clean one in this office" in frame.decline


def test_a_word_that_names_a_thing_of_the_office_is_that_thing() -> None:
    frame = _default("the stapler is jammed, bring me a paper one")
    assert [t.item for t in frame.tasks] == ["paper"]
