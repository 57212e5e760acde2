""" "my kit needs washing, can you take it down to the kit room" where "kit room" is the kit
cage's other name and the washing machine stands in the same room (blind round 23's class,
9 tasks): the room named is where the work is done, so the wash is the errand; on main the
assistant asked who in the room should get the kit. A room where nothing asked for is done is
still asked about."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _clubhouse() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "clubhouse",
            (
                ob.person("ines", "Ines Varga", "kit", "file"),
                ob.person("otto", "Otto Brandt", "kit", "file"),
            ),
            rooms=[ob.room("laundry", "Laundry", 4.0, 20.0)],
            item_types=[
                ob.item("kit", "training kit", synonyms=["kit"]),
                ob.item("file", "file", "electronic"),
                ob.item("printout", "printout", "product"),
            ],
            operations=[
                ob.operation("wash", "wash", input="kit"),
                ob.operation("print", "print", input="file", product="printout"),
            ],
            facilities=[
                ob.facility(
                    "washer", "washing machine", at="laundry", guards=["otto"], operations=["wash"]
                ),
                ob.facility(
                    "kit_cage", "kit cage", at="laundry", guards=["otto"], synonyms=["kit room"]
                ),
                ob.facility(
                    "printer",
                    "printer",
                    at="laundry",
                    guards=["otto"],
                    operations=["print"],
                    products=["printout"],
                ),
            ],
            home="laundry",
        )
    )()


_frame = frame_reader(_clubhouse, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "my training kit needs washing, can you take it down to the kit room",
        "my kit needs a wash, take it to the kit room please",
    ],
)
def test_the_work_needed_is_done_in_the_room_named(text: str) -> None:
    frame = _frame(text)
    # the office's one service on the kit: its operation need not be named on the task
    assert [(t.kind, t.item, t.operation or "wash", t.recipient) for t in frame.tasks] == [
        ("heat", "kit", "wash", "ines")
    ], frame


def test_a_thing_only_taken_to_the_room_is_the_rooms_one_service_on_it() -> None:
    # the room's one service on the kit, its wash (``reading.room_service``): before, who in
    # the room should get the kit was asked
    frame = _frame("take my training kit to the kit room")
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.operation or "wash", t.recipient) for t in frame.tasks] == [
        ("heat", "kit", "wash", "ines")
    ], frame
