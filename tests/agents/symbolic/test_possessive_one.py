"""Whose one, said after a pause with the thing's pro-form: "I need the moisture meter that
lives in the drying room, Seun's one" asks for Seun's meter, as "..., Seun's" does (fix103d,
class 1's analogue; ``reading.possessive_corrections``). Before, "one" after the possessive
made it say something else, and anyone's meter was fetched."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from helpers.reading import frame_reader
from helpers.seed_lab import seed_lab

_lab = frame_reader(seed_lab, "ines")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("I need the moisture meter that lives in the drying room, Seun's one", "seun"),
        ("I need the moisture meter that lives in the drying cabinet, Seun's one", "seun"),
        ("I need the moisture meter, Mateus's one please", "mateus"),
    ],
)
def test_the_owner_said_with_one_is_whose_thing(text: str, owner: str) -> None:
    frame = _lab(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [
        ("transfer", "moisture_meter", owner)
    ], frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("I need the stapler that lives in the print room, Zhang's one", "zhang"),
        ("bring me Hu's stapler, Gao's one", "gao"),  # a correction, as "..., Gao's"
    ],
)
def test_the_same_on_the_default_office(text: str, owner: str) -> None:
    assert tasks_of("default", text, "sun") == [("transfer", "stapler", owner, "sun")]


# -- must not change: "one" that says something of the thing ------------------------------
@pytest.mark.parametrize(
    "text", ["I need a stapler, Zhang's one is broken", "I need a stapler, not Zhang's one"]
)
def test_one_that_says_something_else_names_no_owner(text: str) -> None:
    assert tasks_of("default", text, "sun") == [("transfer", "stapler", None, "sun")]
