"""A thing named first and alone, as an exclamation or a fragment ("tape!!!", "staples...",
"gloves -"), then a container or measure of it asked for from a place ("a roll from the
cupboard") is some of that thing from there (screen/rewrites.container_of_named), never a
thing of its own the store lacks ("there is no roll at the supply cabinet"). A container
asked for with nothing named before it, a thing of the office's own name, and a container
said with what it holds read as before. The office is small and written here: a supply
cabinet of shared consumables in a supply room."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.reading import frame_reader


def _raw() -> dict[str, Any]:
    people = (
        ob.person("kit", "Kit Harte", "mug", "stapler"),
        ob.person("ana", "Ana Brook", "mug"),
        ob.person("tom", "Tom Reyes", "mug"),
    )
    raw = ob.office_file(
        "stock room",
        people,
        rooms=[
            ob.room("supply_room", "Supply room", 4.0, 20.0),
            ob.room("kitchen", "Kitchen", 10.0, 20.0),
        ],
        item_types=[
            ob.item("staples", "staples", consumable=True),
            ob.item("paper", "paper", consumable=True, synonyms=["printer paper"]),
            ob.item("gloves", "gloves", consumable=True),
            ob.item("tape", "tape", consumable=True, synonyms=["sticky tape"]),
            ob.item("tissues", "tissues", consumable=True),
            ob.item("mug", "mug"),
            ob.item("stapler", "stapler"),
            ob.item("power_bank", "power bank"),
            ob.item("coffee", "coffee", "product"),
        ],
        operations=[ob.operation("coffee", "brew", name="make coffee", product="coffee")],
        facilities=[
            ob.facility(
                "cabinet",
                "supply cabinet",
                at="supply_room",
                guards=["tom"],
                supplies=("staples", "paper", "gloves", "tape", "tissues", "power_bank"),
                synonyms=["cabinet", "cupboard", "stores"],
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=["ana"],
                operations=["coffee"],
                products=["coffee"],
            ),
        ],
        home="supply_room",
    )
    return raw


_read = frame_reader(ob.parsed(_raw), "kit")


@pytest.mark.parametrize(
    ("text", "supply"),
    [
        ("paper!! printer ate the lot, a ream from the supply room pls", "paper"),
        ("staples... ran out again, grab me a box from the cabinet?", "staples"),
        ("gloves - used my last pair, a box from the stores when you can", "gloves"),
        ("tape!!! a roll from the cupboard please", "tape"),
        ("tissues! a handful from the cabinet pls", "tissues"),
        ("sticky tape!! could you grab me a roll from the supply room", "tape"),
    ],
)
def test_a_container_after_a_thing_named_alone_is_that_thing(text: str, supply: str) -> None:
    frame = _read(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", supply, "kit")], (
        frame.tasks
    )


# -- must not change ---------------------------------------------------------------------


def test_a_container_with_nothing_named_before_it_is_still_declined() -> None:
    frame = _read("a box from the stores pls")
    assert frame.tasks == [] and "no box" in (frame.decline or ""), frame


def test_a_thing_of_its_own_after_a_thing_named_alone_is_that_thing() -> None:
    for text in ("a power bank from the cupboard", "stapler!! a power bank from the cupboard"):
        frame = _read(text)
        assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "power_bank")], text


def test_an_unknown_thing_after_a_thing_named_alone_is_still_declined() -> None:
    # "lamp" is no container: not a lamp of tape
    frame = _read("tape!!! a lamp from the cupboard")
    assert frame.tasks == [] and "no lamp" in (frame.decline or ""), frame


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("my stapler ran out, a box of staples pls", ["staples"]),
        ("a coffee and a box of tissues", ["coffee", "tissues"]),
        ("I ran out of staples. Could you bring me a box?", ["staples"]),
    ],
)
def test_a_container_said_with_its_thing_reads_as_before(text: str, items: list[str]) -> None:
    frame = _read(text)
    assert frame.decline is None and frame.question is None, frame
    assert [t.item for t in frame.tasks] == items, frame.tasks


def test_a_container_of_one_singular_thing_is_not_that_thing() -> None:
    # no box holds one stapler: the box is not read as the stapler
    frame = _read("stapler! a box from the cupboard please", "ana")
    assert not any(t.item == "stapler" for t in frame.tasks), frame.tasks
