""" "my sarnies" (blind round 24's class): everyday names of sandwiches are the office's
thing called sandwiches (its lunch, here), as "a cuppa" is its tea; on main the assistant said
it knew no sarnies at the fridge."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _staff_room() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "staff room",
            (
                ob.person(
                    "ines",
                    "Ines Varga",
                    ob.kept("lunch", at="kitchen", facility="fridge"),
                ),
                ob.person("otto", "Otto Brandt"),
            ),
            rooms=[ob.room("kitchen", "Kitchen", 4.0, 20.0)],
            item_types=[ob.item("lunch", "lunch", "personal", synonyms=["sandwiches"])],
            operations=[],
            facilities=[ob.facility("fridge", "staff fridge", at="kitchen", guards=["otto"])],
            home="kitchen",
        )
    )()


_frame = frame_reader(_staff_room, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "can u fetch my sarnies from the fridge pls, not had a break since 7",
        "bring me my butty from the fridge",
    ],
)
def test_the_everyday_name_is_the_offices_thing(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "lunch", "ines", "ines")
    ], frame
