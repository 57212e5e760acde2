"""A purpose the office lists, said with more words: an article ("check *the* tread depth"
where "check tread depth" is listed), nouns the object goes on with ("check the tread
*wear*") or words after it ("... on a customer's tyres", "... for the audit") still name the
item listed for it; and a decline never says a thing the office has does not exist
(issue #23). Offices built here on the default and on harbour."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml

_TOOLS = [
    {
        "id": "tread_gauge",
        "name": "tread depth gauge",
        "purposes": ["measure tread", "check tread depth", "check the tread"],
    },
    {
        "id": "damp_meter",
        "name": "moisture meter",
        "purposes": ["measure the moisture", "check damp"],
    },
]
_REQUESTER = {"default": "lee", "harbour": "may"}
_OWNER = {"default": "chen", "harbour": "grace"}


@functools.cache
def _parser(base: str) -> InstructionParser:
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE if base == "default" else HARBOUR_FILE)
    raw["item_types"] += [dict(t) for t in _TOOLS]
    for p in raw["people"]:
        if p["id"] == _OWNER[base]:
            p["owns"] = [*p.get("owns", []), *({"type": t["id"], "known": True} for t in _TOOLS)]
    return InstructionParser(parse_office(raw, f"{base} with a garage's tools"))


@pytest.mark.parametrize("base", ["default", "harbour"])
@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need something to check the tread depth on a customer's tyres", "tread_gauge"),
        ("I need something to check the tread depth for the audit", "tread_gauge"),
        ("can I get something to check the tread wear on the van", "tread_gauge"),
        ("I need something to measure tread pattern", "tread_gauge"),
        ("I need something to measure moisture levels in the cellar", "damp_meter"),
        ("can I have something to check the damp in the archive", "damp_meter"),
    ],
)
def test_listed_purpose_said_longer_names_its_item(base: str, text: str, item: str) -> None:
    frame = _parser(base).parse(text, _REQUESTER[base])
    assert [t.item for t in frame.tasks] == [item]
    assert frame.decline is None


@pytest.mark.parametrize("base", ["default", "harbour"])
def test_an_office_thing_is_never_declined_as_missing(base: str) -> None:
    # the item's name misread with a word glued on: asked about, never "there is no ..."
    frame = _parser(base).parse("bring me a tread depth gauge wear", _REQUESTER[base])
    assert not frame.tasks
    assert frame.decline is None
    assert frame.question


@pytest.mark.parametrize("base", ["default", "harbour"])
def test_a_thing_the_office_lacks_is_still_declined(base: str) -> None:
    # must not change: no one here has a tyre inflator
    frame = _parser(base).parse("bring me a tyre inflator", _REQUESTER[base])
    assert not frame.tasks
    assert frame.decline is not None and "no tyre inflator" in frame.decline
