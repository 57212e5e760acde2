"""Words of what the office's services make, said in a form its names do not list: "scan my
signed waybill to PDF" where the product is "scanned PDF" (no "pdf" synonym) is the result's
form, never someone called PDF; "photocopy my form and bring me the copies" names the copy
the photocopy makes, never an unknown thing to ask about (blind rounds 77 and 72 after this
stop's first fixes)."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, default_office_that_scans
from helpers.reading import frame_reader


def _scans_to_pdf() -> Office:
    product = {"id": "scan_pdf", "name": "scanned PDF", "synonyms": ["pdf scan"]}
    return default_office_that_scans("scan_pdf", product, pdf_names_files=False)


_scanning = frame_reader(_scans_to_pdf, "wang")
_default = frame_reader(default_office, "wang")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Can you scan my signed document to PDF for me?",
        "scan my document to PDF please",
        "could you scan my printed document into PDF",
        # the service's verb in another form (blind round 89: "I need my access request form
        # scanned to PDF for the customer" asked who PDF is)
        "I need my document scanned to PDF",
        "can my document be scanned into PDF please",
        "my document needs scanning to PDF",
    ],
)
def test_a_products_word_after_to_is_the_results_form(text: str) -> None:
    frame = _scanning(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == [("copy", "document", "wang")]
    assert frame.tasks[0].operation == "scan_pdf"


@pytest.mark.parametrize(
    "text", ["take my stapler to Bob", "my document was scanned, take it to Bob"]
)
def test_an_unknown_capitalised_name_after_to_is_still_asked_about(text: str) -> None:
    """Not a product's word: "take my stapler to Bob" still asks who Bob is."""
    frame = _scanning(text)
    assert frame.question is not None and "Bob" in frame.question, frame.question


@pytest.mark.parametrize(
    "text",
    [
        "photocopy my document and bring me the copies",
        "copy my document and bring me the copy",
    ],
)
def test_the_product_of_the_requests_own_service_is_no_unknown_thing(text: str) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == [("copy", "document", "wang")]


def test_an_unknown_thing_beside_a_service_is_still_asked_about() -> None:
    frame = _default("photocopy my document and bring me the projector")
    assert frame.question is not None and "projector" in frame.question, frame.question
