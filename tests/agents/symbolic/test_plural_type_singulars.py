"""The singular of a type's plural name that is also a verb ("wipe" of "wipes", "swab" of
"swabs", "towel" of "towels") is that type where it is asked for: after its article, right
after the one it is for ("bring me a wipe", "hand Zhang a wipe") or a verb of asking or
having ("I need a wipe", "could I have a swab"). After a thing or "it" ("give the desk a
wipe", "give it a wipe") it is the act done to the thing, left as it was
(``reading.measured_items``)."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers import office_builder as ob
from helpers.dataset_offices import default_office
from helpers.reading import frame_reader


def _raw_clinic() -> dict[str, Any]:
    """A clinic's back room: supplies with plural names whose singulars are verbs too."""
    people = (
        ob.person("ivo", "Ivo Brandt", "mug"),
        ob.person("rhea", "Rhea Sandoval", "mug"),
        ob.person("odile", "Odile Marsh", "mug"),
    )
    supplies = ("swabs", "towels")
    return ob.office_file(
        "clinic",
        people,
        rooms=[ob.room("store", "Store room", 4.0, 20.0)],
        item_types=[
            ob.item("swabs", "swabs", synonyms=["cotton swabs"], consumable=True),
            ob.item("towels", "paper towels", synonyms=["towels"], consumable=True),
            ob.item("mug", "mug"),
        ],
        operations=[],
        facilities=[
            ob.facility("cabinet", "store cabinet", at="store", guards=["odile"], supplies=supplies)
        ],
        home="store",
    )


_clinic = frame_reader(ob.parsed(_raw_clinic), "ivo")
_default = frame_reader(default_office, "lee")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("bring me a wipe", "lee"),  # the class's analogue (was "there is no wipe")
        ("could I have a wipe", "lee"),
        ("i need a wipe please", "lee"),
        ("hand Zhang a wipe", "zhang"),
    ],
)
def test_default_the_singular_asked_for_is_the_wipes(text: str, to: str) -> None:
    frame = _default(text)
    assert frame.decline is None, frame.decline
    assert [(k, i, r) for k, i, r in _tasks(frame)] == [("transfer", "wipes", to)], frame


@pytest.mark.parametrize(
    ("text", "item", "to"),
    [
        ("bring me a swab", "swabs", "ivo"),
        ("could I have a towel", "towels", "ivo"),
        ("pass Rhea a swab please", "swabs", "rhea"),
    ],
)
def test_clinic_the_singular_asked_for_is_the_type(text: str, item: str, to: str) -> None:
    frame = _clinic(text)
    assert frame.decline is None and frame.question is None, (frame.decline, frame.question)
    assert _tasks(frame) == [("transfer", item, to)], frame


@pytest.mark.parametrize(
    "text",
    [
        # the act done to a thing: declined today as a thing the office has not (nothing
        # moves), never the office's wipes fetched
        "give the desk a wipe",
        "give it a wipe",
        "give my monitor a quick wipe",
    ],
)
def test_must_not_change_the_act_is_no_wipes(text: str) -> None:
    frame = _default(text)
    assert not any(t.item == "wipes" for t in frame.tasks), frame
    assert frame.decline is not None and "wipe in this office" in frame.decline, frame


def test_must_not_change_clinic_the_act_on_a_thing() -> None:
    assert not any(t.item == "towels" for t in _clinic("give the bench a towel").tasks)


def test_the_singular_of_a_plain_synonym_is_still_read() -> None:
    # "tissues" → "tissue", never a verb: read as before
    assert _tasks(_default("bring me a tissue")) == [("transfer", "wipes", "lee")]
