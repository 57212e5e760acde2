"""A room named after "on" ("need some paper on the floor", "drop it with Wang on the
floor"), where the room is a facility whose service the assistant cannot run, says where
the thing is wanted or where the person is, as "in the meeting room" does: no "I can't help
with the studio floor" (blind round 86's class; the offices and sentences here are the
tests' own, built from the default office and harbour with a room called by a short name)."""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any

import pytest

from assistantx.core.office import Office, load_office, parse_office
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml

_DATA = Path(__file__).parents[3] / "dataset"


def _renamed(path: Path, facility: str, name: str, synonyms: list[str]) -> Office:
    """The office at ``path`` with ``facility`` (a room nobody's service is run in) called
    ``name``, and ``synonyms`` its short names."""
    raw: dict[str, Any] = raw_yaml(path)
    for row in raw["facilities"]:
        if row["id"] == facility:
            row["name"], row["synonyms"] = name, synonyms
    return parse_office(raw, raw["name"])


@functools.cache
def _studio() -> Office:
    return _renamed(_DATA / "office.yaml", "meeting_room", "studio floor", ["floor", "studio"])


@functools.cache
def _harbour_deck() -> Office:
    path = _DATA / "offices" / "harbour" / "office.yaml"
    return _renamed(path, "lounge", "roof deck", ["deck"])


_studio_frame = frame_reader(_studio, "mao")
_deck_frame = frame_reader(_harbour_deck, "mark")
_default = frame_reader(load_office, "mao")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("need some paper on the floor, the marks are peeling", "paper"),
        ("I need a stapler on the studio floor", "stapler"),
        ("could you bring me some paper on the floor please", "paper"),
    ],
)
def test_a_need_on_the_room_is_brought_to_the_speaker(text: str, item: str) -> None:
    frame = _studio_frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, "mao")], frame


def test_a_printout_dropped_with_a_colleague_on_the_room_goes_to_them() -> None:
    frame = _studio_frame("print my file and drop it with Wang on the floor")
    assert [t.recipient for t in frame.tasks][-1:] == ["wang"], frame
    assert frame.question is None and frame.decline is None, frame


def test_harbour_with_a_deck_reads_the_same() -> None:
    frame = _deck_frame("need a tape dispenser on the deck, the boxes need sealing")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("tape", "mark")], frame


def test_the_room_asked_for_its_own_service_is_still_refused() -> None:
    frame = _studio_frame("book the floor")
    assert frame.tasks == [] and frame.decline is not None, frame


def test_in_the_meeting_room_is_kept() -> None:
    frame = _default("need some paper in the meeting room")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("paper", "mao")], frame
