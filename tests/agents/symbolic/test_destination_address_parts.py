"""A destination outside the office keeps all its parts (blind rounds 61-62's class: a send
went to a place cut short at its first comma, and the judge counted the wrong place): after
"to", the place runs to the end of its clause, over the comma-joined parts of an address ("St
Luke's, Ward 4", "Acme Ltd, 3 Mill Lane, Leeds", "the Royal Infirmary, pharmacy"), and stops
before a clause of its own (", thanks", ", it has to go today", "so that ...", "because ...",
"please")."""

from __future__ import annotations

import pytest

from helpers.courier_room import courier_room
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
