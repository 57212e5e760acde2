"""The table of task kinds: every consumer's view of a kind comes from one entry."""

from __future__ import annotations

from typing import get_args

from assistantx.core import task_kinds
from assistantx.core.goals import PREDICATES
from assistantx.core.office import Operation
from assistantx.core.ports.lock import WORK_PURPOSES, Purpose
from assistantx.core.task_schema import MILESTONE_KIND, PART_TASK_KIND, SHAPE_KIND
from assistantx.core.wording import PURPOSE_TEXT, done_words


def test_each_kind_has_one_milestone_the_goals_know() -> None:
    for spec in task_kinds.KINDS:
        assert spec.milestone in PREDICATES
        assert MILESTONE_KIND[spec.milestone] == spec.id


def test_part_kinds_and_shapes_come_from_the_table() -> None:
    assert PART_TASK_KIND["get_file"] == "send_file"
    assert PART_TASK_KIND["make"] == "produce"
    assert SHAPE_KIND == {
        "render": "print",
        "transform": "copy",
        "make": "produce",
        "treat": "heat",
    }


def test_work_steps_are_lock_purposes_with_words() -> None:
    assert set(WORK_PURPOSES) == {"sign", "seal", "copy", "heat"}
    assert WORK_PURPOSES <= set(get_args(Purpose))
    for purpose in WORK_PURPOSES:
        assert "{item}" in PURPOSE_TEXT[purpose]


def test_the_plain_work_pattern_is_in_then_worked_then_out() -> None:
    assert task_kinds.works_on_item("heat")
    assert task_kinds.works_on_item("sign")
    assert not task_kinds.works_on_item("transfer")
    assert not task_kinds.works_on_item("send_file")
    assert [s.purpose for s in task_kinds.kind("seal").steps] == ["deposit", "seal", "collect"]


def test_an_operation_says_what_it_did_with_its_own_verb() -> None:
    assert done_words(Operation(id="shred", name="shred")) == "shredded"
    assert done_words(Operation(id="fax", name="fax")) == "faxed"
    assert done_words(Operation(id="heat", name="heat")) == "heated"
    scan = Operation(id="pdf", name="scan to PDF", done="scanned to PDF")
    assert done_words(scan) == "scanned to PDF"
