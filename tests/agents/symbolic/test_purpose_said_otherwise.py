"""A thing asked for by its purpose, said in other words than the office's data ("something
to get dog hairs off a guest's coat" where the lint roller's purposes say "get hair off";
"something to open a parcel with" where the box cutter's say "open parcels"): the purpose is
the same with an article, a plural or a noun that only modifies its object, and what the
purpose acts on ("a guest's coat", "my trousers", "the visitor's bag") is never a thing to
fetch. A purpose no item declares is read as before."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE, default_office
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml

_ROLLER = {
    "id": "lint_roller",
    "name": "lint roller",
    "purposes": ["remove fluff", "get fluff off", "get hair off"],
}
_CUTTER = {"id": "box_cutter", "name": "box cutter", "purposes": ["open parcels", "cut card"]}


def _with_tools(path: Any, owner: str) -> Office:
    """The office at ``path`` with a lint roller and a box cutter, both ``owner``'s."""
    raw = raw_yaml(path)
    raw["item_types"] += [_ROLLER, _CUTTER]
    person = next(p for p in raw["people"] if p["id"] == owner)
    person.setdefault("owns", []).extend([{"type": "lint_roller"}, {"type": "box_cutter"}])
    return parse_office(raw)


_harbour = frame_reader(functools.cache(lambda: _with_tools(HARBOUR_FILE, "ken")), "will")
_default = frame_reader(functools.cache(lambda: _with_tools(DEFAULT_FILE, "lin")), "mao")


@pytest.mark.parametrize("read", [_harbour, _default])
@pytest.mark.parametrize(
    ("text", "item"),
    [
        (
            "need something to get dog hairs off a guest's coat before she goes in to dinner",
            "lint_roller",
        ),
        ("need something to get fluff off my jacket", "lint_roller"),
        ("I need something to get cat hair off the visitor's bag", "lint_roller"),
        ("could I have something to get fluff off my trousers", "lint_roller"),
        ("I need something to open a parcel with", "box_cutter"),
        ("need something to open the parcels", "box_cutter"),
    ],
)
def test_the_item_whose_purpose_is_said_is_found(read: Any, text: str, item: str) -> None:
    frame = read(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", item)], frame


def test_a_purpose_said_as_declared_is_read_as_before() -> None:
    frame = frame_reader(default_office, "mao")("I need something to write with")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "pen")], frame


def test_a_purpose_no_item_declares_brings_nothing() -> None:
    # nothing here polishes: the shoes are never fetched, whatever is made of the request
    frame = _harbour("need something to polish my shoes with")
    assert not any(t.item not in (None, "lint_roller", "box_cutter") for t in frame.tasks), frame
    assert not frame.tasks or frame.question is not None or frame.decline is not None, frame
