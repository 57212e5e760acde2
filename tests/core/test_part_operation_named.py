"""A dataset part's kind picks the operation it names when several of the office's operations
have its shape: blind round 95's orchestra office listed its scan to PDF before its photocopier,
both copy a document, and ``{kind: copy}`` ("photocopy my parts pls") was labelled as the scan
(the reader, rightly, photocopied, and failed against the label). Where the kind names none of
them or several, the base must say which, with ``operation:``."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.core.task_spec import Part, part_operation
from helpers.dataset_offices import DEFAULT_FILE
from helpers.yaml_files import raw_yaml


def _office(*first: dict[str, Any]) -> Office:
    """The default office with ``first`` listed before its own operations, each done at the
    printer, so a copy-shaped one comes before its photocopier."""
    raw = raw_yaml(DEFAULT_FILE)
    raw["item_types"].append({"id": "duplicate_copy", "name": "duplicate", "kind": "product"})
    raw["operations"] = [*first, *raw["operations"]]
    printer = next(f for f in raw["facilities"] if f["id"] == "printer")
    printer["operations"] += [op["id"] for op in first]
    return parse_office(raw)


SCAN = {
    "id": "scan",
    "name": "scan to PDF",
    "verbs": ["scan"],
    "input": "document",
    "product": "file",
}
DUPLICATE = {
    "id": "duplicate",
    "name": "duplicate",
    "verbs": ["duplicate", "copy"],
    "input": "document",
    "product": "duplicate_copy",
}


def test_the_kind_picks_the_operation_it_names_not_the_first_listed() -> None:
    office = _office(SCAN)
    assert [o.id for o in office.with_shape("transform")][:2] == ["scan", "copy"]
    assert part_operation(office, Part(kind="copy")).id == "copy"
    assert part_operation(office, Part(kind="copy", operation="scan")).id == "scan"


def test_a_kind_several_operations_answer_to_must_be_named() -> None:
    office = _office(DUPLICATE)  # "copy" is the photocopier's id and the duplicator's verb
    with pytest.raises(ValueError, match=r"several operations do copy here .*operation:"):
        part_operation(office, Part(kind="copy"))
    assert part_operation(office, Part(kind="copy", operation="duplicate")).id == "duplicate"


def test_one_operation_of_the_shape_needs_no_name() -> None:
    office = _office()
    assert part_operation(office, Part(kind="copy")).id == "copy"
