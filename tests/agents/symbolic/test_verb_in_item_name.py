"""A destructive verb that begins one of the office's item names is the item
(``screen.verb_in_item_name``): "bin bags to Tomas please" delivers the stores' bin bags,
"scrap paper to Tomas" and "cut flowers to Tomas" likewise, where "bin", "scrap" and "cut"
are otherwise verbs the reader declines or takes as a call-off. The verb followed by anything
that is no such name ("bin the old bags", "bin these rubbish bags", "cut up Tomas's mug")
keeps its verb reading, and so does an office's own service verb before a thing whose name
begins with its agent noun ("shred the shredder bags")."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers import office_builder as ob
from helpers.reading import frame_reader
from helpers.stores_cupboard import raw_stores, stores

_stores = frame_reader(stores, "ada")


def _raw_shredding_stores() -> dict[str, Any]:
    """The stores with a shredder that shreds documents and keeps shredder bags."""
    raw = raw_stores()
    raw["item_types"] += [
        ob.item("document", "document", "personal", signable=True),
        ob.item("shredder_bags", "shredder bags", consumable=True),
    ]
    raw["operations"] = [ob.operation("shred", "shred", input="document", consumes=True)]
    raw["facilities"].append(
        ob.facility(
            "shredder",
            "shredder",
            at="stores",
            guards=["nell"],
            operations=["shred"],
            supplies=["shredder_bags"],
        )
    )
    for person in raw["people"]:
        person["owns"].append({"type": "document", "known": True})
    return raw


_shredding = frame_reader(ob.parsed(_raw_shredding_stores), "ada")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("bin bags to Tomas please", "bin_bags"),
        ("bin bags for Tomas please", "bin_bags"),
        ("scrap paper to Tomas please", "scrap_paper"),
        ("cut flowers to Tomas please", "cut_flowers"),
        ("cut flowers for Tomas's desk please", "cut_flowers"),
    ],
)
def test_a_verb_that_opens_an_item_name_is_the_item(text: str, item: str) -> None:
    frame = _stores(text)
    assert frame.decline is None, frame.decline
    assert _tasks(frame) == [("transfer", item, "tomas")], (frame.question, frame.decline)


def test_bin_bags_to_a_desk_asks_who_as_any_item_does() -> None:
    """The item, then the office's usual question about a desk (no decline)."""
    frame = _stores("bin bags to desk 2 please")
    assert frame.decline is None, frame.decline
    assert "who there should get it" in (frame.question or ""), frame.question


@pytest.mark.parametrize(
    "text",
    ["bin the old bags", "bin these rubbish bags", "bin Tomas's mug", "please bin the bags"],
)
def test_the_verb_before_another_object_is_still_declined(text: str) -> None:
    frame = _stores(text)
    assert frame.tasks == []
    assert "I won't bin" in (frame.decline or ""), frame.decline


def test_cut_up_a_colleagues_thing_is_still_declined() -> None:
    frame = _stores("cut up Tomas's mug")
    assert frame.tasks == []
    assert "I won't cut up Tomas Reyes's things" in (frame.decline or ""), frame.decline


def test_shred_the_shredder_bags_keeps_its_verb_reading() -> None:
    """Must not change: the service verb stays the verb; the bags are no document, so no
    fetch of them happens."""
    frame = _shredding("shred the shredder bags")
    assert not any(t.kind == "transfer" and t.item == "shredder_bags" for t in frame.tasks)
    assert frame.tasks == [] or all(t.kind != "transfer" for t in frame.tasks), frame.tasks


def test_shredder_bags_alone_are_fetched() -> None:
    frame = _shredding("shredder bags to Tomas please")
    assert _tasks(frame) == [("transfer", "shredder_bags", "tomas")], frame.question
