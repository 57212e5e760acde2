"""A colleague's electronic file "of", "about" or "on" one of the office's things is that
colleague's file for the speaker: the thing after the preposition says what the file is
about, never a second thing asked for (issue #23). Default office, and harbour with a
"manifest" listed as a document."""

from __future__ import annotations

import functools
from typing import Any

import pytest
from _offices import tasks_of

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.dataset_offices import HARBOUR_FILE
from helpers.yaml_files import raw_yaml


@functools.cache
def _harbour_parser() -> InstructionParser:
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    for t in raw["item_types"]:
        if t["id"] == "document":
            t["synonyms"] = [*t.get("synonyms", []), "manifest"]
    return InstructionParser(parse_office(raw, "harbour with manifests"))


def _harbour(text: str) -> list[tuple[str, str | None, str | None, str | None]]:
    frame = _harbour_parser().parse(text, "may")
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("I need Wang's pdf of the contract", "wang"),
        ("can I have Zhang's slides about the invoice", "zhang"),
        ("I need Wang's pdf of the budget", "wang"),
        ("can I have Zhang's slides for the review", "zhang"),
    ],
)
def test_default_file_of_a_thing_is_the_colleagues_file(text: str, owner: str) -> None:
    assert tasks_of("default", text, "lee") == [("send_file", "file", owner, "lee")]


@pytest.mark.parametrize(
    ("text", "owner", "recipient"),
    [
        ("I need Faith's pdf of the manifest", "faith", "may"),
        ("I need Ray's spreadsheet about the manifest", "ray", "may"),
        ("send Ray's pdf of the manifest to Grace", "ray", "grace"),
    ],
)
def test_harbour_file_of_a_thing_is_the_colleagues_file(
    text: str, owner: str, recipient: str
) -> None:
    assert _harbour(text) == [("send_file", "file", owner, recipient)]


def test_the_thing_itself_is_still_the_thing() -> None:
    # must not change: "Ray's manifest" alone is his paper, brought
    assert _harbour("send Ray's manifest to Grace") == [("transfer", "document", "ray", "grace")]


def test_a_file_sent_on_is_unchanged() -> None:
    # must not change: "send Wang's pdf to Zhang"
    assert tasks_of("default", "send Wang's pdf to Zhang", "lee") == [
        ("send_file", "file", "wang", "zhang")
    ]


def test_a_box_of_paper_is_still_paper() -> None:
    # must not change: a thing of no electronic kind "of" another is that other's measure
    assert tasks_of("default", "I need Wang's box of paper", "lee") == [
        ("transfer", "paper", "wang", "lee")
    ]
