"""A head noun said as a unit after a count: "my cylinder's down to 150 bar, can you get it
filled" in an office whose hydrant key is also called a "hydrant bar" (round 229's class,
read after its final measure) asked what to do with the hydrant key; "bar" after 150 is the
unit of pressure, and the cylinder is filled. "bring me a bar" and "bring me 2 bars" still
name the hydrant key."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.reading import frame_reader

_PEOPLE = (
    ob.person("hazel", "Hazel Ngata", "cylinder", aliases=["Hazel"]),
    ob.person("rob", "Rob Page", "cylinder", "hydrant_key", aliases=["Rob"]),
)


def _station() -> dict[str, Any]:
    return ob.office_file(
        "fire station",
        _PEOPLE,
        rooms=[ob.room("ba_room", "BA room", 10.0, 20.0)],
        item_types=[
            ob.item("cylinder", "BA cylinder", "personal", synonyms=["cylinder"]),
            ob.item(
                "hydrant_key",
                "hydrant key",
                synonyms=["hydrant bar", "standpipe key", "key and bar"],
            ),
        ],
        operations=[ob.operation("fill", "fill", "refill", name="fill", input="cylinder")],
        facilities=[
            ob.facility(
                "compressor", "compressor", at="ba_room", guards=["rob"], operations=["fill"]
            )
        ],
        home="ba_room",
    )


_hazel = frame_reader(ob.parsed(_station), "hazel")


@pytest.mark.parametrize(
    "text",
    [
        "my cylinder's down to 150 bar, can you get it filled",
        "my cylinder is only at 50 bar, could you fill it",
    ],
)
def test_a_unit_after_a_count_is_no_thing(text: str) -> None:
    frame = _hazel(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("heat", "cylinder", "hazel", "hazel")
    ], frame


@pytest.mark.parametrize("text", ["bring me a bar", "bring me 2 bars", "bring me Rob's bar"])
def test_the_head_noun_still_names_the_thing(text: str) -> None:
    frame = _hazel(text)
    assert [t.item for t in frame.tasks] == ["hydrant_key"], frame
