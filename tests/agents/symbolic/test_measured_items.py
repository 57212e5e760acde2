"""An item named by a unit or a container of it (``reading.measured_items``): "a post-it
pad", "a box of staples", "a copier paper ream", "a ream of copier paper" are the office's
supply, and the singular of a plural name ("a post-it" of "post-its", "a bin bag") is the
same item where a counted noun stands. A request part that names a thing no name of the
office reads, beside a part that does, is asked about, never dropped while the other part
runs (``reading.unnamed_things``: a wish with a source, "I need a flux pad from the
cupboard", and a joined thing before a source or after "some ..."). On a small stores office
built for it, the default office and harbour."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader
from helpers.stores_cupboard import stores

_stores = frame_reader(stores, "ada")
_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "pat")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need a post-it pad from the cupboard", "sticky_notes"),
        ("bring me a post-it please", "sticky_notes"),
        ("bring me a post-it note", "sticky_notes"),
        ("bring me a box of staples", "staples"),
        ("could you get me a packet of staples", "staples"),
        ("a copier paper ream please", "copier_paper"),
        ("bring me a ream of copier paper", "copier_paper"),
        ("could you get me a bin bag", "bin_bags"),
        ("a wipe pack for me please", "wipes"),
        ("bring me a tub of hand gel", "sanitiser"),
    ],
)
def test_stores_unit_names_the_item(text: str, item: str) -> None:
    frame = _stores(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [("transfer", item, None, "ada")]


def test_two_packs_for_a_colleague() -> None:
    assert _tasks(_stores("two packs of wipes for Tomas please")) == [
        ("transfer", "wipes", None, "tomas")
    ]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("bring me a box of wipes", "wipes"),
        ("bring me a pack of wipes please", "wipes"),
        ("bring me a sheet of paper", "paper"),
    ],
)
def test_default_unit_names_the_item(text: str, item: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(k, i) for k, i, _, _ in _tasks(frame)] == [("transfer", item)]


def test_harbour_roll_of_tape() -> None:
    frame = _harbour("bring me a roll of tape")
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(k, i) for k, i, _, _ in _tasks(frame)] == [("transfer", "tape")]


def test_both_parts_run_with_a_unit_named_item() -> None:
    frame = _stores("I need a post-it pad from the cupboard and Tomas's mug")
    assert _tasks(frame) == [
        ("transfer", "sticky_notes", None, "ada"),
        ("transfer", "mug", "tomas", "ada"),
    ]


@pytest.mark.parametrize(
    "text",
    [
        "can you post it to Tomas",  # the verb and its object, no post-it
        "give the desk a wipe",  # an act, no wipes fetched
        "bring me a box",  # a unit of nothing named
    ],
)
def test_must_not_change_no_item_read(text: str) -> None:
    frame = _stores(text)
    assert not any(t.item in ("sticky_notes", "wipes") for t in frame.tasks), frame.tasks


def test_must_not_change_default_post_it_is_the_verb() -> None:
    frame = _default("could you post it to Sun Li")
    assert frame.tasks == [] and "post" in (frame.decline or ""), frame.decline


@pytest.mark.parametrize(
    ("office", "text", "part"),
    [
        ("stores", "I need a flux pad from the cupboard and a mug from Tomas", "a flux pad"),
        ("stores", "I need a flux pad from the cupboard, and bring me Tomas's mug", "a flux pad"),
        ("stores", "bring me Tomas's mug and a flux pad from the cupboard", "a flux pad"),
        ("stores", "get me some staples and a gizmo pad from the cupboard", "a gizmo pad"),
        ("stores", "get me some staples and a gizmo pad", "a gizmo pad"),
        ("default", "I need a lamp from the print room and a stapler from Sun Li", "a lamp"),
        ("default", "I need a stapler from Sun Li and a lamp from the print room", "a lamp"),
    ],
)
def test_an_unread_part_is_asked_not_dropped(office: str, text: str, part: str) -> None:
    frame = (_stores if office == "stores" else _default)(text)
    assert frame.tasks == [], frame.tasks
    assert f"what you mean by “{part}”" in (frame.question or ""), frame.question


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # must not change: a wish with no source is no errand ("I need a break")
        ("I need a break, bring me Tomas's mug", [("transfer", "mug", "tomas", "ada")]),
        ("get me some staples and a mug from Tomas", None),
    ],
)
def test_must_not_change_known_parts(
    text: str, tasks: list[tuple[str, str, str, str]] | None
) -> None:
    frame = _stores(text)
    assert "what you mean by" not in (frame.question or ""), frame.question
    if tasks is not None:
        assert _tasks(frame) == tasks
