"""After an operation's verb, "to" and a word of one of the office's products is the form of
the result ("scan to PDF my signed contract"), never a recipient nor a verb: the reader
(``result_form``) keeps it the product. Before, in an office whose scan makes a "scanned PDF"
(synonyms "pdf", "scan"), "scan to PDF my signed contract" asked "I don't know anyone called
'PDF'". Tested on two offices built here from the dataset's default and harbour offices,
with a participle before the noun ("my signed contract", "my printed notes")."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import operation_of
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml

_PDF = {"name": "scanned PDF", "synonyms": ["pdf", "scan"], "kind": "electronic"}


def _without_pdf(raw: dict[str, Any]) -> None:
    """The office's own file type no longer called "pdf": the scan's product is."""
    for t in raw["item_types"]:
        t["synonyms"] = [s for s in t.get("synonyms", []) if s != "pdf"]


@functools.cache
def _default_that_scans() -> Office:
    raw = raw_yaml(DEFAULT_FILE)
    _without_pdf(raw)
    raw["item_types"].append({"id": "scanned_pdf", **_PDF})
    raw["operations"].append(
        {"id": "scan", "name": "scan", "verbs": ["scan"], "input": "document"}
        | {"product": "scanned_pdf"}
    )
    printer = next(f for f in raw["facilities"] if f["id"] == "printer")
    printer["operations"].append("scan")
    printer["products"].append("scanned_pdf")
    return parse_office(raw)


@functools.cache
def _harbour_that_scans_to_pdf() -> Office:
    raw = raw_yaml(HARBOUR_FILE)
    _without_pdf(raw)
    scan = next(t for t in raw["item_types"] if t["id"] == "scan")
    scan.update(_PDF)
    return parse_office(raw)


_DEFAULT = frame_reader(_default_that_scans, "lee")
_HARBOUR = frame_reader(_harbour_that_scans_to_pdf, "mark")


@pytest.mark.parametrize(
    "text",
    [
        "Can you scan my signed contract to PDF for me?",
        "scan to PDF my signed contract please",
        "scan to pdf my printed notes",
        "could you scan into a PDF my signed form",
    ],
)
def test_default_the_pdf_is_what_the_scan_makes(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.recipient) for t in frame.tasks] == [("document", "lee")]
    assert operation_of(_default_that_scans(), frame.tasks[0]) == "scan"


@pytest.mark.parametrize(
    "text",
    [
        "Can you scan my signed contract to PDF for me?",
        "scan to PDF my signed contract please",
        "please scan to pdf my printed timesheet",
    ],
)
def test_harbour_the_pdf_is_what_the_scan_makes(text: str) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("copy", "document", "mark")]


def test_a_colleague_after_to_is_the_recipient() -> None:
    """Neighbour: "to May" after the thing is whom it goes to."""
    frame = _HARBOUR("scan my contract to May")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("document", "may")]


def test_an_unknown_name_after_to_is_still_asked() -> None:
    """Neighbour: a capitalised word that is no product is still asked about."""
    frame = _DEFAULT("scan to Bertrand my signed contract")
    assert not frame.tasks and frame.question is not None
    assert "Bertrand" in frame.question
