"""A room named by the first word of its name, said bare after "to" ("take my wheel down to
wrapping" for the "Wrapping room"), is that room (``reading.bare_room``): its services on the
thing are asked about, where the thing had been handed back to the speaker. "to wrapping
paper" (a noun after it) and "the wrapping" stay the English word; the default office and
harbour have no such room ("meeting" and "print" name other things)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from helpers import office_builder as ob
from helpers.dataset_offices import default_office, harbour_office
from helpers.office_builder import Row
from helpers.reading import frame_reader


def _raw() -> Row:
    people = (
        ob.person("colm", "Colm Doyle", "cheese"),
        ob.person("marta", "Marta Ferreira", "cheese"),
    )
    return ob.office_file(
        "dairy",
        people,
        rooms=[
            ob.room("wrapping_room", "Wrapping room", 20.0, 20.0),
            ob.room("mess", "Mess", 4.0, 20.0, kind="room"),
            # a bench named by the same first word leaves "wrapping" the room's
            ob.room("wrapping_bench", "Wrapping bench", 24.0, 20.0, kind="workstation"),
        ],
        item_types=[{"id": "cheese", "name": "cheese", "synonyms": ["wheel"]}],
        operations=[
            ob.operation("wax", "wax", input="cheese"),
            ob.operation("vacuum_pack", "vacuum pack", input="cheese"),
        ],
        facilities=[
            ob.facility(
                "wax_bath", "wax bath", at="wrapping_room", guards=["marta"], operations=["wax"]
            ),
            ob.facility(
                "vac_packer",
                "vacuum packer",
                at="wrapping_room",
                guards=["marta"],
                operations=["vacuum_pack"],
            ),
        ],
        home="mess",
    )


_colm = frame_reader(ob.parsed(_raw), "colm")


@pytest.mark.parametrize(
    "text",
    ["can you take my wheel down to wrapping", "can you take my wheel into wrapping pls"],
)
def test_a_room_said_by_its_first_word_is_the_room(text: str) -> None:
    frame = _colm(text)
    assert frame.tasks == [], frame
    assert frame.question is not None and "Wrapping room" in frame.question, frame
    assert "wax it" in frame.question, frame


def test_in_and_the_word_before_a_noun_name_no_room() -> None:
    # "in wrapping" is how a thing is done as often as where: never rewritten
    said = _colm("can you wax my wheel in wrapping")
    assert "Wrapping room" not in " ".join(e.words for e in said.evidence), said


def test_the_english_word_before_a_noun_is_no_room() -> None:
    # must not change: "wrapping paper" names no room, nothing rewritten
    frame = _colm("take my wheel down to wrapping paper")
    assert frame.question is None or "Wrapping room" not in frame.question, frame


@pytest.mark.parametrize("office", [default_office, harbour_office])
def test_the_dataset_offices_have_no_bare_room(office: object) -> None:
    parser = InstructionParser(office())  # type: ignore[operator]
    assert parser.surface.bare_room.rooms == {}
