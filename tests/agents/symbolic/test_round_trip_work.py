"""A thing taken to a room and brought back is the work that room's facility does on it, read
from the office's data (the operation there that takes this kind of thing): "my lunch is
cold, take it to the kitchenette and bring it back" heats it, "take my document to the copy
room, then back to me" scans it where the copy room's scanner is the one that takes documents.
With no return said, the room's one service on the thing is still done
(``reading.room_service``); a thing no operation there takes, or a colleague it is for,
changes nothing: who there gets it is asked, or the colleague gets it."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "wu")
_HARBOUR = frame_reader(harbour_office, "bill")


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        (
            "My lunch is cold. Could you take it to the kitchenette and bring it back after?",
            "heat",
            "lunch",
        ),
        ("take my lunch to the kitchenette and back please", "heat", "lunch"),
        ("could you run my lunch over to the kitchenette and then back to me?", "heat", "lunch"),
        # the print room's printer prints files and copies documents: a document is copied
        ("take my document to the print room, then back to me", "copy", "document"),
    ],
)
def test_default_office_round_trip_is_the_rooms_work(text: str, kind: str, item: str) -> None:
    frame = _DEFAULT(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [(kind, item, "wu", "wu")], frame


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        (
            "My badge is ready to laminate. Could you take it to the badge office and bring "
            "it back after?",
            "heat",  # the laminating's shape: work on the thing, returned
            "badge",
        ),
        ("take my badge to the badge office and back", "heat", "badge"),
        # the copy room holds a printer (files) and a scanner (documents): the scanner's work
        ("could you take my document to the copy room and then back to me?", "copy", "document"),
    ],
)
def test_harbour_round_trip_is_the_rooms_work(text: str, kind: str, item: str) -> None:
    frame = _HARBOUR(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [(kind, item, "bill", "bill")], frame
    assert "to the" not in frame.evidence[0].words, frame  # the room's work, not a delivery


@pytest.mark.parametrize(
    "text",
    [
        "take my mug to the kitchenette",  # no return, no work on mugs: who there is asked
        "take my mug to the kitchenette and bring it back",  # nothing there works on mugs
    ],
)
def test_default_office_no_round_trip_work_asks_who_there(text: str) -> None:
    frame = _DEFAULT(text)
    assert not frame.tasks, frame
    assert frame.question is not None and "who there" in frame.question, frame


def test_default_office_no_return_said_is_still_the_rooms_one_service() -> None:
    # "take my lunch to the kitchenette": the microwave is the room's one service on a lunch
    # (``reading.room_service``); before, who there should get it was asked
    frame = _DEFAULT("take my lunch to the kitchenette")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("heat", "lunch", "wu", "wu")
    ], frame


def test_taken_to_the_room_for_a_colleague_is_a_hand_over() -> None:
    frame = _HARBOUR("take my badge to the badge office for Max")
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", "badge", "bill", "max")], frame
