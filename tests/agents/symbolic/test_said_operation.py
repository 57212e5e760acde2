"""The product of a service, named after it, is what goes on (``reading.said_operation``):
in an office whose scanner scans to PDF (an electronic product) beside a photocopier on the
same paper, "scan my report and send the pdf to Wang" sends the scan's PDF to Wang, never the
scan to the speaker and the speaker's own file to Wang. The verb said ("scan") picks the
operation; "copy ... and send the pdf" and an owned file ("send Wang my file") stay as said."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _scan_to_pdf() -> Office:
    """The default office with a scan to PDF at its printer, beside the photocopy."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    raw["item_types"].append(
        {"id": "pdf_scan", "name": "PDF scan", "synonyms": ["scan", "scans"], "kind": "electronic"}
    )
    raw["operations"].append(
        {
            "id": "scan",
            "name": "scan to PDF",
            "verbs": ["scan"],
            "input": "document",
            "product": "pdf_scan",
        }
    )
    for facility in raw["facilities"]:
        if facility["id"] == "printer":
            facility["operations"].append("scan")
            facility["products"].append("pdf_scan")
    return parse_office(raw)


@functools.cache
def _harbour_scan_to_pdf() -> Office:
    """Harbour with its scanner's product electronic (a scan to PDF)."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    for item in raw["item_types"]:
        if item["id"] == "scan":
            item["kind"] = "electronic"
    return parse_office(raw)


_DEFAULT = frame_reader(_scan_to_pdf, "lin")
_HARBOUR = frame_reader(_harbour_scan_to_pdf, "will")


def _tasks(frame: Any) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.operation, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("scan my paperwork and get the pdf over to Wang", "wang"),  # the class's analogue
        ("scan my report and send the pdf to Wang", "wang"),
        ("scan my report and give the PDF to Zhang", "zhang"),
        ("scan my report and send me the pdf", "lin"),  # to the speaker (asked on main)
    ],
)
def test_the_scans_pdf_goes_where_it_is_sent(text: str, recipient: str) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("copy", "document", "scan", recipient)], frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("scan my document and get the scan over to Grace", "grace"),
        ("scan my form and send the pdf to Mark", "mark"),
        ("scan my document and send me the pdf", "will"),
    ],
)
def test_the_scans_pdf_goes_where_it_is_sent_on_harbour(text: str, recipient: str) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("copy", "document", recipient)
    ], frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # must not change: the speaker's own file, named as theirs, is a send of its own
        (
            "scan my report and send Wang my file",
            [("copy", "document", "scan", "lin"), ("send_file", "file", None, "wang")],
        ),
        # must not change: a photocopy makes paper; "the pdf" is the speaker's file
        (
            "copy my report and send the pdf to Wang",
            [("copy", "document", "copy", "lin"), ("send_file", "file", None, "wang")],
        ),
        # must not change: the copy, named after the copy, handed over
        ("copy my report and get the copy over to Wang", [("copy", "document", "copy", "wang")]),
    ],
)
def test_an_owned_file_or_a_paper_copy_is_read_as_before(
    text: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == tasks, frame
