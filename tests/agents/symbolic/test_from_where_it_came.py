""" "from <an unknown capitalised word>" after a thing whose owner is said is where it came
from (fix129d, class 5): "can I get Miles's logs from Suzuka?" asked who Miles is (two Miles:
fine), then "I don't know anyone called 'Suzuka'". A thing with a possessive right before it
has its owner already, so an unknown name after "from" (no colleague, alias or place of the
office) is context, a place outside, whatever kind of thing it is (readings.py
``_paper_about``; papers were read so before, files were not). "can I get the report from
Wang" (Wang's) and "can I get the file from Berlin" (no owner said: still asked) are read as
before."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_lin = frame_reader(default_office, "lin")
_may = frame_reader(harbour_office, "may")


def _raw_pit() -> dict[str, Any]:
    return ob.office_file(
        "pit wall",
        (
            ob.person("miles_a", "Miles Archer", aliases=["Miles"]),
            ob.person("miles_b", "Miles Brook", aliases=["Miles"]),
            ob.person("nell", "Nell Ode", aliases=["Nell"]),
        ),
        rooms=[ob.room("garage", "Garage", 4.0, 20.0)],
        item_types=[ob.item("logs", "telemetry logs", "electronic", synonyms=["logs"])],
        everyone_owns=["logs"],
        operations=[],
        facilities=[],
        home="garage",
    )


_nell = answered_reader(ob.parsed(_raw_pit), "nell")


@pytest.mark.parametrize(
    ("text", "kind", "item", "owner"),
    [
        ("can I get Wang's report from Shanghai?", "transfer", "document", "wang"),
        ("can I get Zhang's file from Berlin please", "send_file", "file", "zhang"),
        ("can I get Zhang's file from Shanghai please", "send_file", "file", "zhang"),
        ("could you get me Wang's budget file from Lisbon", "send_file", "file", "wang"),
    ],
)
def test_the_unknown_name_is_where_it_came_from(
    text: str, kind: str, item: str, owner: str
) -> None:
    frame = _lin(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (kind, item, owner, "lin")
    ], frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("can I get Ray's file from Lisbon?", "ray"),
        ("could I have Grace's file from Osaka", "grace"),
    ],
)
def test_the_same_in_harbour(text: str, owner: str) -> None:
    frame = _may(text)
    assert frame.question is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("file", owner, "may")]


def test_after_the_owner_is_answered_the_place_is_not_asked_about() -> None:
    asked = _nell("can I get Miles's logs from Suzuka?")
    assert asked.question is not None and "Miles" in asked.question, asked
    frame = _nell("can I get Miles's logs from Suzuka?", ["Miles Brook"])
    assert frame.question is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("logs", "miles_b", "nell")]


def test_from_a_colleague_names_the_owner_as_before() -> None:
    frame = _lin("can I get the report from Wang")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("document", "wang", "lin")]


def test_a_thing_with_no_owner_said_still_asks_who_the_name_is() -> None:
    frame = _lin("can I get the file from Berlin")
    assert frame.tasks == [], frame
    assert frame.question is not None and "'Berlin'" in frame.question, frame
