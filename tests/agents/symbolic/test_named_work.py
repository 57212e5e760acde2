"""An office operation named by a verb and its object ("apply corrections", "update the
register") is asked for by that verb and object, whatever stands between them; the thing the
work is done "to" is the item worked on, which comes back (round 160, class 3;
``reading.named_work``). A sentence with the verb but not the object, or that hands the
thing on, keeps its own reading."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.reading import frame_reader
from helpers.repro_room import repro_room
from helpers.yaml_files import raw_yaml

_repro = frame_reader(repro_room, "bram")


def _with_work(path: Any, name: str, op: dict[str, Any], at: str, guard: str) -> Office:
    """A dataset office with one more operation, named by verb and object, at a desk."""
    raw: dict[str, Any] = raw_yaml(path)
    raw["operations"].append(op)
    raw["facilities"].append(
        {
            "id": "work_desk",
            "name": "work desk",
            "location": at,
            "operations": [op["id"]],
            "guards": [guard],
        }
    )
    return parse_office(raw, name)


def _harbour() -> Office:
    op = {"id": "tag", "name": "apply asset tags", "input": "calculator"}
    return _with_work(HARBOUR_FILE, "harbour with asset tags", op, "supply_room", "dawn")


def _default() -> Office:
    op = {"id": "redact", "name": "remove personal details", "input": "document"}
    return _with_work(DEFAULT_FILE, "default with redaction", op, "print_room", "xu")


_harbour_frame = frame_reader(_harbour, "may")
_default_frame = frame_reader(_default, "zhou")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the class's analogues
        (
            "apply this week's corrections to my charts pls",
            ("heat", "chart", "bram", "bram", "correct"),
        ),
        (
            "apply this week's Notices to Mariners corrections to my charts",
            ("heat", "chart", "bram", "bram", "correct"),
        ),
        ("could you update my register for me", ("heat", "register", "bram", "bram", "log")),
        # variants: nothing between, another owner's thing, another inflection
        ("apply corrections to my chart", ("heat", "chart", "bram", "bram", "correct")),
        (
            "could you apply the latest corrections to Cleo's chart?",
            ("heat", "chart", "cleo", "bram", "correct"),
        ),
        ("updating my register would be great", ("heat", "register", "bram", "bram", "log")),
    ],
)
def test_the_operation_is_named_by_verb_and_object(text: str, expected: tuple[str, ...]) -> None:
    frame = _repro(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        expected
    ], frame


@pytest.mark.parametrize(
    ("reader", "text", "expected"),
    [
        (
            _harbour_frame,
            "apply the new asset tags to my calculator please",
            ("heat", "calculator", "may", "may", "tag"),
        ),
        (
            _harbour_frame,
            "can you apply asset tags to my calculator",
            ("heat", "calculator", "may", "may", "tag"),
        ),
        (
            _default_frame,
            "remove the personal details from my document",
            ("heat", "document", "zhou", "zhou", "redact"),
        ),
    ],
)
def test_the_same_on_the_dataset_offices(reader: Any, text: str, expected: tuple[str, ...]) -> None:
    frame = reader(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        expected
    ], frame


@pytest.mark.parametrize(
    ("reader", "text", "expected"),
    [
        # the thing handed on, no work named
        (_repro, "bring my charts to Cleo", [("transfer", "chart", "bram", "cleo", None)]),
        (
            _harbour_frame,
            "bring my calculator to Will",
            [("transfer", "calculator", "may", "will", None)],
        ),
        # the work, then the thing handed on: two tasks, in order
        (
            _repro,
            "apply the corrections, then bring my charts to Cleo",
            [
                ("heat", "chart", "bram", "bram", "correct"),
                ("transfer", "chart", "bram", "cleo", None),
            ],
        ),
    ],
)
def test_the_verb_without_its_object_keeps_its_reading(
    reader: Any, text: str, expected: list[tuple[str | None, ...]]
) -> None:
    frame = reader(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == expected


def test_a_verb_with_another_object_names_no_work() -> None:
    assert _repro("apply for leave for me").tasks == []


def _default_rig() -> Office:
    """The default office with a check named by verb and object, at a machine whose name
    holds the object's word ("run diagnostics" at the "diagnostics rig")."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    op = {"id": "check", "name": "run diagnostics", "verbs": ["diagnose"], "input": "document"}
    raw["operations"].append(op)
    raw["facilities"].append(
        {
            "id": "rig",
            "name": "diagnostics rig",
            "location": "print_room",
            "operations": ["check"],
            "guards": ["xu"],
        }
    )
    return parse_office(raw, "default with a diagnostics rig")


_rig_frame = frame_reader(_default_rig, "zhou")


@pytest.mark.parametrize(
    "text",
    [
        # the machine's name holds the work's object: the word is the machine's (blind round
        # 211: the object's word was taken from the machine's name, and the thing between
        # went with it: "What should I do, with which item?")
        "run my document through the diagnostics rig",
        "could you run my document through the diagnostics rig please",
        # the work named whole, as before
        "run diagnostics on my document",
        "could you diagnose my document",
    ],
)
def test_a_word_of_a_machines_name_is_not_the_works_object(text: str) -> None:
    frame = _rig_frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("heat", "document", "zhou", "zhou", "check")
    ], frame
