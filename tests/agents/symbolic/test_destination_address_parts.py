"""A destination outside the office keeps all its parts (blind rounds 61-62's class: a send
went to a place cut short at its first comma, and the judge counted the wrong place): after
"to", the place runs to the end of its clause, over the comma-joined parts of an address ("St
Luke's, Ward 4", "Acme Ltd, 3 Mill Lane, Leeds", "the Royal Infirmary, pharmacy"), and stops
before a clause of its own (", thanks", ", it has to go today", "so that ...", "because ...",
"please")."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.courier_room import courier_room, raw_courier_room
from helpers.reading import frame_reader

_frame = frame_reader(courier_room, "bjorn")


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("Can my contract go by courier to St Luke's, Ward 4?", "St Luke's, Ward 4"),
        ("courier my contract to St Luke's, Ward 4 please", "St Luke's, Ward 4"),
        ("courier my form to Acme Ltd, 3 Mill Lane, Leeds", "Acme Ltd, 3 Mill Lane, Leeds"),
        (
            "courier my contract to Acme Ltd, 3 Mill Lane, Leeds, thanks",
            "Acme Ltd, 3 Mill Lane, Leeds",
        ),
        (
            "courier my contract to Acme Ltd, 3 Mill Lane, Leeds so that they get it today",
            "Acme Ltd, 3 Mill Lane, Leeds",
        ),
        (
            "dispatch my form to the Royal Infirmary, pharmacy please",
            "the Royal Infirmary, pharmacy",
        ),
        (
            "send my contract by courier to the Royal Infirmary, main reception",
            "the Royal Infirmary, main reception",
        ),
        ("could you courier my statement to Hale House, Level 2, thanks", "Hale House, Level 2"),
        # a clause of its own after the place is no part of it
        ("courier my contract to Acme Ltd so that they get it today", "Acme Ltd"),
        ("courier my contract to Acme Ltd because they need it", "Acme Ltd"),
        ("courier my contract to Acme Ltd, it has to go today", "Acme Ltd"),
        ("courier my contract to Smith and Sons, Leeds", "Smith and Sons, Leeds"),
        ("courier my contract to the head office", "the head office"),
        # a numbered street line longer than a town's ("Unit 4 Dockside Road")
        (
            "courier my form to Baxter Steel Ltd, Unit 4 Dockside Road",
            "Baxter Steel Ltd, Unit 4 Dockside Road",
        ),
        (
            "courier my form to Baxter Steel Ltd, Unit 4 Dockside Road, thanks",
            "Baxter Steel Ltd, Unit 4 Dockside Road",
        ),
        # a number to dial after the place, whatever the place looks like
        ("courier my form to Dr Osei's clinic, 01632 960442", "Dr Osei's clinic, 01632 960442"),
        ("courier my form to the clinic, 01632 960442 please", "the clinic, 01632 960442"),
        # a proper name with its joining words
        ("courier my form to Dr Okafor, School of Pharmacy", "Dr Okafor, School of Pharmacy"),
        # must not change: a small number is no number to dial, a lower-case clause no street
        ("courier my form to the clinic, 3 please", "the clinic"),
        ("courier my form to Baxter Steel Ltd, it has to go by 4 today", "Baxter Steel Ltd"),
    ],
)
def test_the_destination_keeps_its_address_parts(text: str, place: str) -> None:
    frame = _frame(text)
    assert [(t.operation, t.destination) for t in frame.tasks] == [("courier", place)], frame


@pytest.mark.parametrize(
    "text",
    [
        "could you courier my contract to Crown Court for me",
        "courier my contract to Crown Court for us please",
    ],
)
def test_whom_it_is_for_is_no_part_of_the_place(text: str) -> None:
    frame = _frame(text)
    assert [t.destination for t in frame.tasks] == ["Crown Court"], frame


def _with_a_colleague_called_ward() -> dict[str, Any]:
    raw = raw_courier_room()
    raw["people"].append(
        {
            **raw["people"][-1],
            "id": "ward",
            "name": "Ward Ellis",
            "aliases": ["Ward"],
            "handle": "@ward",
        }
    )
    return raw


_ward_frame = frame_reader(ob.parsed(_with_a_colleague_called_ward), "bjorn")


@pytest.mark.parametrize(
    ("text", "place"),
    [
        # a colleague's name followed by a number is a part of the place, not the colleague
        ("Can my contract go by courier to St Luke's, Ward 4?", "St Luke's, Ward 4"),
        ("courier my form to the Royal Infirmary, Ward 12 please", "the Royal Infirmary, Ward 12"),
    ],
)
def test_a_colleagues_name_before_a_number_is_part_of_the_place(text: str, place: str) -> None:
    frame = _ward_frame(text)
    assert [(t.operation, t.destination) for t in frame.tasks] == [("courier", place)], frame


def test_a_colleagues_name_after_the_comma_still_ends_the_place() -> None:
    frame = _ward_frame("courier my contract to St Luke's, Ward")
    assert [t.destination for t in frame.tasks] == ["St Luke's"], frame
