"""The table of task kinds: every consumer's view of a kind comes from one entry."""

from __future__ import annotations

from assistantx.core import task_kinds
from assistantx.core.goals import PREDICATES
from assistantx.core.office import Operation
from assistantx.core.task_schema import SHAPE_KIND, Part
from assistantx.core.wording import done_words, locker_text


def test_each_kind_has_one_milestone_the_goals_know() -> None:
    for spec in task_kinds.kinds():
        assert spec.milestone in PREDICATES
        assert task_kinds.of_milestone(spec.milestone) == spec


def test_part_kinds_and_shapes_come_from_the_table() -> None:
    assert Part(kind="get_file", owner="lee").task_kind() == "send_file"
    assert Part(kind="make", item="coffee").task_kind() == "produce"
    assert SHAPE_KIND == {
        "render": "print",
        "transform": "copy",
        "make": "produce",
        "treat": "heat",
    }


def test_work_steps_are_lock_purposes_with_words() -> None:
    assert task_kinds.work_purposes() == {"sign", "seal", "copy", "heat"}
    assert task_kinds.work_purposes() <= set(task_kinds.purposes())
    for purpose in task_kinds.work_purposes():
        assert "{item}" in (locker_text(purpose) or "")


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
