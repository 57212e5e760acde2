"""A short given name said by an alias of it and the surname ("Dan Okonkwo" for Daniel
Okonkwo) calls that colleague by "Dan" alone, as the full name's first word does; where two
colleagues are so called, which one is asked (round 207, read: "dan needs headphones", with two
Daniels, had fetched headphones for the speaker, "dan" read as no one)."""

from __future__ import annotations

import pytest

from helpers.office_builder import item, office_file, parsed, person, room
from helpers.reading import frame_reader


def _studio_raw(*, two: bool) -> dict[str, object]:
    people = [
        person("daniel_o", "Daniel Okonkwo", "headphones", aliases=["Dan Okonkwo", "Okonkwo"]),
        person("rosa", "Rosa Delgado"),
    ]
    if two:
        people.append(person("daniel_l", "Daniel Lindgren", aliases=["Dan Lindgren", "Lindgren"]))
    return office_file(
        "Studio",
        people,
        rooms=[room("desk_room", "Desk room", 5.0, 5.0)],
        item_types=[item("headphones", "headphones")],
        operations=[],
        facilities=[],
        home="desk_room",
    )


_two = frame_reader(parsed(lambda: _studio_raw(two=True)), "rosa")
_one = frame_reader(parsed(lambda: _studio_raw(two=False)), "rosa")


@pytest.mark.parametrize("text", ["dan needs headphones", "bring Dan some headphones"])
def test_two_dans_are_asked_about(text: str) -> None:
    frame = _two(text)
    assert not frame.tasks, frame
    assert frame.question is not None and "Daniel Okonkwo" in frame.question, frame
    assert "Daniel Lindgren" in frame.question, frame


def test_one_dan_is_that_colleague() -> None:
    frame = _one("bring Dan some headphones")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("headphones", "daniel_o")], frame


def test_the_alias_said_whole_is_the_one_colleague() -> None:
    frame = _two("bring Dan Okonkwo some headphones")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("headphones", "daniel_o")], frame
