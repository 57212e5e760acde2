"""A colleague said to have some *in* a place of the office ("Siobhán usually has them in the
key press") names that place as where the things are: she only looks after them there. Round
231 asked "I don't know of any location case key of Siobhán Byrne's", and a word of the key
press's own name ("key") had been read back as the key itself ("the location case key
press"). A colleague said to have one with no place after it still names whom to borrow
from."""

from __future__ import annotations

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _depot() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Depot",
            [
                ob.person("amara", "Amara Nwosu", aliases=["Amara"]),
                ob.person("siobhan", "Siobhán Byrne", "stapler", aliases=["Siobhán"]),
            ],
            rooms=[ob.room("key_room", "Key room", 20.0, 6.0)],
            item_types=[
                ob.item("key", "location case key", synonyms=["loc key", "case key"]),
                ob.item("stapler", "stapler"),
            ],
            operations=[],
            facilities=[
                ob.facility(
                    "key_cabinet",
                    "key cabinet",
                    at="key_room",
                    guards=["siobhan"],
                    synonyms=["key press"],
                    supplies=[{"type": "key", "count": 2}],
                )
            ],
            home="key_room",
        )
    )()


_frame = frame_reader(_depot, "amara")


def test_a_colleague_has_them_in_a_place_names_the_place() -> None:
    frame = _frame(
        "I need a loc key for the 23 location. Siobhán usually has them in the key press."
    )
    assert frame.question is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("key", "key_cabinet", "amara")
    ], frame


def test_the_place_said_alone_is_read_as_before() -> None:
    frame = _frame("I need a loc key, the key press has some")
    assert [(t.item, t.owner) for t in frame.tasks] == [("key", "key_cabinet")], frame


def test_a_colleague_has_one_with_no_place_is_whom_to_borrow_from() -> None:
    frame = _frame("I need a stapler, Siobhán has one")
    assert [(t.item, t.owner) for t in frame.tasks] == [("stapler", "siobhan")], frame
