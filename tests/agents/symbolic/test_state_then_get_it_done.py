"""A thing's state said, then "get it <done form>" (fixer 59g class 3): "my cylinder's down to
150 bar, can you get it filled" asks the operation the participle names ("fill") on the
speaker's thing named in the first clause, handed back; never another thing of the office (a
key). Guards: these read right before the fixer's change too (the class's failure did not
reproduce on these offices); "can you get it filled" alone asks which, and "get me a filled
one" is no operation on the speaker's thing."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.dive_van import raw_dive_van
from helpers.reading import frame_reader


def _dive_van_with_radios_and_a_key() -> Office:
    """The dive van with the breathing cylinder so named, Lee's own cylinder and radio, a
    charging rack for radios, and a key Ruth owns (the other thing of the office)."""
    raw: dict[str, Any] = raw_dive_van()
    for t in raw["item_types"]:
        if t["id"] == "cylinder":
            t["name"], t["synonyms"] = "breathing cylinder", []
    raw["item_types"] += [{"id": "key", "name": "key"}, {"id": "radio", "name": "radio"}]
    for p in raw["people"]:
        if p["id"] == "lee":
            p["owns"] += [{"type": "cylinder", "known": True}, {"type": "radio", "known": True}]
        if p["id"] == "ruth":
            p["owns"] += [{"type": "key", "known": True}]
    raw["operations"].append(ob.operation("charge", "charge", input="radio"))
    raw["facilities"].append(
        ob.facility("rack", "charging rack", at="workshop", guards=["dara"], operations=["charge"])
    )
    return parse_office(raw)


_van = frame_reader(_dive_van_with_radios_and_a_key, "lee")
_harbour = frame_reader(harbour_office, "bill")


@pytest.mark.parametrize(
    ("text", "operation", "item"),
    [
        ("my cylinder's down to 150 bar, can you get it filled", "fill", "cylinder"),
        ("my cylinder is down to 150 bar, can you get it filled?", "fill", "cylinder"),
        ("my radio's on 10%, can you get it charged", "charge", "radio"),
    ],
)
def test_the_state_said_then_get_it_done_works_on_the_speakers_thing(
    text: str, operation: str, item: str
) -> None:
    frame = _van(text)
    assert [(t.operation, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (operation, item, "lee", "lee")
    ], frame


def test_a_scuffed_badge_gets_laminated() -> None:
    frame = _harbour("my badge is all scuffed, can you get it laminated")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("badge", "bill", "bill")]


@pytest.mark.parametrize("text", ["can you get it filled", "get me a filled one"])
def test_with_no_thing_said_it_asks_which(text: str) -> None:  # must not change
    frame = _van(text)
    assert not frame.tasks and frame.question is not None and "Which item" in frame.question
