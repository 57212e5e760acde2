"""The longest name said wins over a shorter name's head inside it, and a paper's name with a
noun of its parts after it is that paper (issue #23).

Offices built here on the default office and harbour, as a hotel's or a trials unit's would
be: an item "card machine" (also "card reader", "card terminal") and the paper also called
"registration card", "reg card", "crf", "consent form". "Rose's card reader" is Rose's card
machine, never her registration card read from the head "card" (``screen.owned_head``: main
handed over her document, or asked what was needed); "my CRF pages need the stamp" is the CRF
stamped (``paper_parts``: main read a statement, or asked what was needed)."""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from assistantx.core.task_schema import Task, TaskFrame
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml

Row = tuple[str, str | None, str | None, str]


@functools.cache
def _parser(base: str) -> InstructionParser:
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE if base == "default" else HARBOUR_FILE)
    for t in raw["item_types"]:
        if t["id"] == "document":
            added = ["registration card", "reg card", "crf", "consent form"]
            t["synonyms"] = [*t.get("synonyms", []), *added]
    raw["item_types"].append(
        {"id": "card_machine", "name": "card machine", "synonyms": ["card reader", "card terminal"]}
    )
    return InstructionParser(parse_office(raw, f"{base} with a card machine"))


def _frame(base: str, text: str, who: str) -> TaskFrame:
    return _parser(base).parse(text, who)


def _rows(tasks: Sequence[Task]) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in tasks]


@pytest.mark.parametrize(
    ("base", "who", "text", "owner"),
    [
        ("harbour", "may", "Please fetch Rose's card reader for me", "rose"),
        ("harbour", "may", "Please fetch Rose's card terminal for me", "rose"),
        ("harbour", "may", "could you grab Jack's card machine for me", "jack"),
        ("default", "lin", "Please fetch Wang's card reader for me", "wang"),
        ("default", "lin", "grab me Lee's card terminal please", "lee"),
    ],
)
def test_the_longer_name_is_the_card_machine(base: str, who: str, text: str, owner: str) -> None:
    """ "card" begins the card machine's name said in full: no registration card is read."""
    assert _rows(_frame(base, text, who).tasks) == [("transfer", "card_machine", owner, who)]


@pytest.mark.parametrize(
    ("base", "who", "text", "owner"),
    [
        ("harbour", "may", "bring me Rose's registration card", "rose"),
        ("harbour", "may", "bring me Rose's reg card", "rose"),
        ("default", "lin", "bring me Wang's registration card", "wang"),
    ],
)
def test_the_papers_own_name_is_still_the_paper(base: str, who: str, text: str, owner: str) -> None:
    assert _rows(_frame(base, text, who).tasks) == [("transfer", "document", owner, who)]


def test_my_card_alone_asks_which() -> None:
    """Bill owns a document (its "registration card") and a badge (its "id card"): "my card"
    is either, asked, never guessed."""
    frame = _frame("harbour", "bring me my card", "bill")
    assert frame.tasks == []
    assert frame.question is not None
    assert "document" in frame.question and "badge" in frame.question


@pytest.mark.parametrize(
    ("base", "who", "text", "expected"),
    [
        (
            "default",
            "lin",
            "My CRF pages need the stamp on them, can you sort that?",
            ("seal", "document", "lin", "lin"),
        ),
        (
            "default",
            "lin",
            "My consent forms need the stamp on them, can you sort that?",
            ("seal", "document", "lin", "lin"),
        ),
        ("default", "lin", "My contract pages need stamping", ("seal", "document", "lin", "lin")),
        (
            "default",
            "lin",
            "My CRF sheets need the stamp on them, can you sort that?",
            ("seal", "document", "lin", "lin"),
        ),
        (
            "default",
            "lin",
            "can you bring me Wang's report copies",
            ("transfer", "document", "wang", "lin"),
        ),
        ("harbour", "may", "bring me Mark's letter pages", ("transfer", "document", "mark", "may")),
        (
            "harbour",
            "may",
            "my timesheet pages need signing by Mark",
            ("sign", "document", "may", "may"),
        ),
    ],
)
def test_a_papers_parts_are_the_paper(base: str, who: str, text: str, expected: Row) -> None:
    assert _rows(_frame(base, text, who).tasks) == [expected]


def test_a_paper_parts_noun_where_nothing_stamps_is_declined_as_the_paper() -> None:
    """Harbour has no seal: the CRF's stamping is declined in words, not read as a fact."""
    frame = _frame("harbour", "My CRF pages need the stamp on them, can you sort that?", "may")
    assert frame.tasks == []
    assert frame.decline is not None and "document" in frame.decline


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bring me some sheets of paper", [("transfer", "paper", None, "lin")]),
        ("make copies of my contract for Wang", [("copy", "document", "lin", "wang")]),
        ("photocopy my report, 3 copies", [("copy", "document", "lin", "lin")]),
    ],
)
def test_must_not_change_parts_said_alone(text: str, expected: list[Row]) -> None:
    """Neighbours: sheets and copies not right after a paper's name keep their reading."""
    assert _rows(_frame("default", text, "lin").tasks) == expected
