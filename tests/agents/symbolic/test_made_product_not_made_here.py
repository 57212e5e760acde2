"""A made thing the office cannot make is declined, never replaced by its input handed over:
"make a copy of my document for Mark" where nothing copies says so and what the office can do
(``screen.made_product``); where the office makes the thing the request is read as before."""

from __future__ import annotations

import functools
from typing import Any

import pytest
from _offices import parser, tasks_of

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.dataset_offices import HARBOUR_FILE
from helpers.yaml_files import raw_yaml


@functools.cache
def _without(operation: str) -> InstructionParser:
    """Harbour with one operation, and every facility's use of it, taken away."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    gone = next(o for o in raw["operations"] if o["id"] == operation)
    raw["operations"].remove(gone)
    for f in raw["facilities"]:
        f["operations"] = [o for o in f["operations"] if o != operation]
        f["products"] = [p for p in f.get("products", []) if p != gone.get("product")]
    return InstructionParser(parse_office(raw, f"harbour without {operation}"))


def _declined(p: InstructionParser, text: str, requester: str) -> str:
    frame = p.parse(text, requester)
    assert frame.tasks == [], frame
    assert frame.decline, frame
    return frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "make a copy of my document for Mark",
        "make Mark a copy of my document",
        "could you make Will a copy of my report",
        "can you run off two copies of my contract for Mark",
        "do me a copy of my document please",
        "make copies of my report for Will",
    ],
)
def test_no_copy_where_nothing_copies(text: str) -> None:
    said = _declined(parser("harbour"), text, "may")
    assert "copies" in said and "What I can do here" in said


@pytest.mark.parametrize(
    ("operation", "text", "word"),
    [
        ("print", "make Mark a printout of my file", "printouts"),
        ("print", "could you make me two printouts of my file", "printouts"),
        ("boil", "make Will a tea", "tea"),
        ("scan", "make Mark a scan of my document", "scans"),
    ],
)
def test_no_product_where_nothing_makes_it(operation: str, text: str, word: str) -> None:
    said = _declined(_without(operation), text, "may")
    assert word in said


def test_coffee_where_no_machine_makes_one() -> None:
    said = _declined(parser("harbour"), "make Mark a coffee", "may")
    assert "coffee" in said


@pytest.mark.parametrize(
    ("office", "text", "who", "tasks"),
    [
        # where the office copies, the copy is made for the one named
        (
            "default",
            "make a copy of my document for Zhang",
            "wang",
            [("copy", "document", "wang", "zhang")],
        ),
        (
            "default",
            "make Zhang a copy of my document",
            "wang",
            [("copy", "document", "wang", "zhang")],
        ),
        # a copy someone holds is their paper itself, handed over
        (
            "harbour",
            "bring Mark my copy of the report",
            "may",
            [("transfer", "document", "may", "mark")],
        ),
        # the speaker's own making: the hand-over asked is done
        (
            "harbour",
            "I'll make a copy myself, just take my document to Mark",
            "may",
            [("transfer", "document", "may", "mark")],
        ),
        (
            "harbour",
            "make sure Mark gets my document",
            "may",
            [("transfer", "document", "may", "mark")],
        ),
        # a product the office makes is still made
        ("harbour", "make me a scan of my document", "may", [("copy", "document", "may", "may")]),
        ("harbour", "can you make me a printout", "may", [("print", "file", "may", "may")]),
    ],
)
def test_must_not_change(
    office: str, text: str, who: str, tasks: list[tuple[str, str, str, str]]
) -> None:
    assert tasks_of(office, text, who) == tasks
