"""A purpose declared as a phrasal verb ("cut off") is said with its object between the verb
and the particle ("something to cut my pots off the wheel with"): the thing declared for it
is meant, and what it works on, and where, is no thing asked for. Round 233 asked "I'm not
sure what you need" (the declared "cut off" was compared with "cut my pots off")."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.purpose_object import said_as_declared
from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _studio() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Studio",
            [
                ob.person("amber", "Amber Kowalczyk", aliases=["Amber"]),
                ob.person("hazel", "Hazel Baker", "cutting_wire", aliases=["Hazel"]),
            ],
            rooms=[ob.room("store", "Clay store", 20.0, 6.0)],
            item_types=[
                ob.item("cutting_wire", "cutting wire", synonyms=["clay wire"])
                | {"purposes": ["cut off"]},
                ob.item("sponge", "sponge") | {"purposes": ["wipe down", "smooth"]},
            ],
            operations=[],
            facilities=[],
            home="store",
        )
    )()


_frame = frame_reader(_studio, "amber")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("need something to cut my pots off the wheel with", "cutting_wire"),
        ("need something to cut my pots off the wheel with, lost mine somewhere", "cutting_wire"),
        ("anything to wipe the bench down with?", "sponge"),
    ],
)
def test_the_object_between_verb_and_particle(text: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, "amber")], frame


@pytest.mark.parametrize(
    ("said", "declared", "expected"),
    [
        ("cut pot off", "cut off", True),
        ("cut my pots off", "cut off", True),
        ("cut off", "cut off", True),
        ("cut pot", "cut off", False),  # no particle said
        ("cut the big heavy pot off", "cut off", False),  # too long to be its object
        ("wipe bench down", "wipe up", False),  # another particle
    ],
)
def test_said_as_declared(said: str, declared: str, expected: bool) -> None:
    assert said_as_declared(said, declared) is expected
