"""A service on the requester's own document "for" an outsider comes back to the requester,
and a credential's name modifying a document names no credential (class 93d-3,
``screen.own_serviced``): "I need my access card form printed for the visitor" prints the
form for the requester instead of declining to hand a card to a visitor; "I need my leave
form scanned to PDF for the client" scans it, the PDF to the requester. A credential itself
for an outsider is still declined, and an outsider named as the recipient ("give it to the
client") still asked about."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office_that_scans, harbour_office
from helpers.reading import frame_reader


@functools.cache
def _scanning() -> Office:
    return default_office_that_scans("scan_pdf", "file")


_default = frame_reader(_scanning, "lee")
_harbour = frame_reader(harbour_office, "rose")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


@pytest.mark.parametrize(
    ("office", "text", "kind", "requester"),
    [
        ("harbour", "I need my access card form printed for the visitor", "print", "rose"),
        ("default", "I need my leave form scanned to PDF for the client", "copy", "lee"),
        # variants of our own: other credentials, documents, services and outsiders
        ("harbour", "print my id card form for the client", "print", "rose"),
        ("harbour", "print my expenses claim form for the customer", "print", "rose"),
        ("default", "scan my leave form to PDF for the customer", "copy", "lee"),
        ("default", "print my leave form for the client", "print", "lee"),
    ],
)
def test_the_product_comes_back_to_the_requester(
    office: str, text: str, kind: str, requester: str
) -> None:
    frame = _read(office, text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        (kind, requester, requester)
    ], frame


def test_the_scan_is_the_scan_to_pdf() -> None:
    frame = _default("I need my leave form scanned to PDF for the client")
    assert [t.operation for t in frame.tasks] == ["scan_pdf"], frame


@pytest.mark.parametrize(
    "text", ["bring my access card to the visitor", "get my access card for the visitor"]
)
def test_a_credential_for_an_outsider_is_still_declined(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [], frame
    assert frame.decline is not None and "keys, cards and passes" in frame.decline, frame


@pytest.mark.parametrize(
    ("office", "text"),
    [
        ("harbour", "I need my access card form printed, give it to the visitor"),
        ("default", "print my leave form and give it to the client"),
        ("harbour", "print my report for the visitor and bring it to him at the gate"),
        ("default", "bring my stapler for the client"),
        ("default", "print Wang's report for the client"),
    ],
)
def test_an_outsider_as_recipient_is_still_asked_about(office: str, text: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "I hand things only to people of this office" in frame.question, frame
