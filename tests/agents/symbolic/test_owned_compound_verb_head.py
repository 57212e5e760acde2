"""After "my", "your", ... an item's name followed by a word that is also one of the office's
task verbs ("my works *order*", where "works" names the file and "order" is a cue) is the
first noun of a compound whose head is that word: no request's verb follows its object, so
the phrase is not read as the item (issue #23). Offices built here on the default and on
harbour, the file given the synonym "works"."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml

_REQUESTER = {"default": "lee", "harbour": "may"}


@functools.cache
def _parser(base: str, listed: bool) -> InstructionParser:
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE if base == "default" else HARBOUR_FILE)
    for t in raw["item_types"]:
        if t["id"] == "file":
            t["synonyms"] = [*t.get("synonyms", []), "works"]
        if t["id"] == "document" and listed:
            t["synonyms"] = [*t.get("synonyms", []), "works order"]
    return InstructionParser(parse_office(raw, f"{base} with works"))


_STAMPED = "I need my works order stamped with the received stamp before it goes to finance"


@pytest.mark.parametrize("base", ["default", "harbour"])
@pytest.mark.parametrize("listed", [True, False])
def test_works_order_is_never_the_file(base: str, listed: bool) -> None:
    frame = _parser(base, listed).parse(_STAMPED, _REQUESTER[base])
    assert all(t.item != "file" for t in frame.tasks)
    assert "electronic file" not in (frame.question or "")


def test_the_longer_listed_name_wins() -> None:
    frame = _parser("default", True).parse(_STAMPED, "lee")
    assert [(t.kind, t.item) for t in frame.tasks] == [("seal", "document")]


def test_the_longer_listed_name_wins_where_nothing_stamps() -> None:
    # harbour has no seal: the document's stamping is declined, the file never read
    frame = _parser("harbour", True).parse(_STAMPED, "may")
    assert not frame.tasks
    assert frame.decline is not None and "document" in frame.decline


@pytest.mark.parametrize("base", ["default", "harbour"])
def test_the_synonym_alone_is_still_the_file(base: str) -> None:
    # must not change: "my works" with nothing after it is the file
    colleague = {"default": "Zhang", "harbour": "Grace"}[base]
    frame = _parser(base, False).parse(f"send my works to {colleague}", _REQUESTER[base])
    assert [t.item for t in frame.tasks] == ["file"]
