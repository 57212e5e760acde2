"""The head noun of an item's name of several words refers back to the item named just before
(``screen.head_noun_back``): "anyone got sticky tape? bring me a dispenser pls" is a fetch of
harbour's tape dispenser, "does anyone have allen keys? bring me a set pls" of a workshop's
hex key set. Said with no such item before it, the head noun keeps today's reading (a thing
the office does not have), and an item named before whose names do not end in it changes
nothing. On harbour and a small workshop built here."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader


def _raw_workshop() -> dict[str, Any]:
    """A workshop whose tools have names of several words (hex key set, glue gun)."""
    people = (
        ob.person("ada", "Ada Holm", "hex_keys", "glue_gun"),
        ob.person("tomas", "Tomas Reyes", "mug"),
        ob.person("nell", "Nell Ortiz", "mug"),
    )
    return ob.office_file(
        "workshop",
        people,
        rooms=[ob.room("bench", "Bench room", 4.0, 20.0)],
        item_types=[
            ob.item("hex_keys", "hex key set", synonyms=["allen keys", "allen key set"]),
            ob.item("glue_gun", "hot glue gun", synonyms=["glue gun"]),
            ob.item("mug", "mug"),
        ],
        operations=[],
        facilities=[],
        home="bench",
    )


_workshop = frame_reader(ob.parsed(_raw_workshop), "tomas")
_harbour = frame_reader(harbour_office, "pat")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("anyone got sticky tape? bring me a dispenser pls", "tape"),
        ("I need sellotape, can you get me the dispenser", "tape"),
        ("who has a laptop charger? bring me an adapter please", "charger"),
    ],
)
def test_harbour_head_noun_is_the_item_named_before(text: str, item: str) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [("transfer", item, "pat")]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("does anyone have allen keys? bring me a set pls", "hex_keys"),
        ("anyone got allen keys? could you fetch me the set", "hex_keys"),
        ("does anyone have a hot glue gun? bring me the gun please", "glue_gun"),
    ],
)
def test_workshop_head_noun_is_the_item_named_before(text: str, item: str) -> None:
    frame = _workshop(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [("transfer", item, "tomas")]


@pytest.mark.parametrize(
    ("office", "text"),
    [
        ("harbour", "bring me a dispenser pls"),
        ("workshop", "bring me a set pls"),
        # an item named before whose names do not end in the head: no reference back
        ("harbour", "anyone got a ruler? bring me a dispenser pls"),
        ("workshop", "anyone got a mug? bring me a set pls"),
    ],
)
def test_a_head_noun_with_nothing_named_before_is_not_the_item(office: str, text: str) -> None:
    frame = (_harbour if office == "harbour" else _workshop)(text)
    assert all(t.item not in ("tape", "hex_keys") for t in frame.tasks), _tasks(frame)
    assert frame.decline is not None or frame.question is not None
