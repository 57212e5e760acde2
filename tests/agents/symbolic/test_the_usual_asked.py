""" "The usual", "my usual", "the same as last time" name nothing the office can know (the robot
keeps no record of what anyone had before): asked for from a place that keeps things, they are
asked about ("Which would you like?", listing what the place keeps), never declined as a thing
the place lacks ("there is no usual at the stores") and never guessed (fix210b class 4). A
thing the place does not keep is still declined, one it keeps still fetched. Checked on a small
works office whose stores keep several consumables, and on harbour's stationery cupboard."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader


def _raw_works() -> dict[str, Any]:
    return ob.office_file(
        "works",
        (
            ob.person("ana", "Ana Costa", "stapler"),
            ob.person("ben", "Ben Okoye", "radio"),
            ob.person("cat", "Cat Lund", "stapler"),
        ),
        rooms=[ob.room("stores", "Stores", 10.0, 20.0), ob.room("yard", "Yard", 20.0, 20.0)],
        item_types=[
            ob.item("stapler", "stapler"),
            ob.item("radio", "radio"),
            ob.item("gloves", "gloves", synonyms=["pair of gloves"], consumable=True),
            ob.item("batteries", "batteries", synonyms=["battery"], consumable=True),
            ob.item("mask", "dust mask", synonyms=["mask", "masks"], consumable=True),
        ],
        operations=[],
        facilities=[
            ob.facility(
                "stores",
                "stores",
                at="stores",
                guards=["ben"],
                supplies=["gloves", "batteries", "mask"],
                synonyms=["store", "the stores"],
            )
        ],
        home="yard",
    )


_works = frame_reader(ob.parsed(_raw_works), "ana")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    "text",
    [
        "could you bring me the usual from stores",
        "could you bring me my usual from the stores",
        "can you grab me the same as last time from stores",
        "bring me the usual from stores please",
    ],
)
def test_the_usual_is_asked_about(text: str) -> None:
    frame = _works(text)
    assert not frame.tasks and frame.decline is None, frame
    assert frame.question is not None, frame
    for kept in ("gloves", "batteries", "dust mask"):
        assert kept in frame.question, frame


def test_the_usual_from_a_cupboard_of_one_thing_is_asked_too() -> None:
    frame = _harbour("could you bring me the usual from the supply cupboard")
    assert not frame.tasks and frame.decline is None, frame
    assert frame.question is not None and "notepad" in frame.question, frame


def test_a_thing_the_stores_lack_is_declined() -> None:
    frame = _works("bring me a unicorn from stores")
    assert not frame.tasks and frame.decline is not None, frame
    assert "unicorn" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [("bring me gloves from stores", "gloves"), ("bring me a mask from the stores", "mask")],
)
def test_a_thing_the_stores_keep_is_fetched(text: str, item: str) -> None:
    frame = _works(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, "ana")], frame


def test_the_answer_names_the_thing() -> None:
    from assistantx.agents.symbolic.reading.parser import InstructionParser

    parser = InstructionParser(ob.parsed(_raw_works)())
    frame = parser.parse_with_answers("could you bring me the usual from stores", "ana", ["gloves"])
    assert [(t.item, t.recipient) for t in frame.tasks] == [("gloves", "ana")], frame


@pytest.mark.parametrize(
    "text", ["bring me the usual gloves from stores", "bring me gloves from stores as usual"]
)
def test_a_thing_said_with_the_habit_is_that_thing(text: str) -> None:
    frame = _works(text)
    assert frame.question is None or "usually" not in frame.question, frame
    assert [t.item for t in frame.tasks] == ["gloves"], frame
