"""Another service's product in a verb's list of objects (fixer 82f, class 3): "copy my
document and a printout" read only the print (the copy was lost). The second thing is what
another service makes, so it is a task of its own: made from that service's own input, the
speaker's (``reading/products_listed.py``). Two verbs said, a product named with its source, a
"copy" after "print" (a "printed copy" is a printout) and a product nothing is made from ("...
and a coffee": asked) read as before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "may")


def _got(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(str(t.kind), t.item, t.owner) for t in frame.tasks]


_COPY = ("copy", "document", "mao")
_PRINT = ("print", "file", "mao")


@pytest.mark.parametrize(
    ("text", "got"),
    [
        # the class's analogue
        ("copy my document and a printout", [_COPY, _PRINT]),
        # variants: other verbs, fillers, counts
        ("could you photocopy my document and also a printout please", [_COPY, _PRINT]),
        ("copy my contract and two printouts", [_COPY, _PRINT]),
        # a "copy" after "print": a "printed copy" is the print's own product, as before
        ("print my file and a copy", [_PRINT]),
        # neighbours: read so already, and still
        ("print my file and a copy of my document", [_PRINT, _COPY]),
        ("copy my document and print my file", [_COPY, _PRINT]),
        ("a copy and a printout of my file", [_COPY, _PRINT]),
    ],
)
def test_each_product_asked_is_made(text: str, got: list[tuple[str, str, str]]) -> None:
    assert _got(_default(text)) == got


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("scan my document and a printout", ["copy", "print"]),
        ("print my file and a scan", ["print", "copy"]),
        ("print my file and scan my document", ["print", "copy"]),
    ],
)
def test_each_product_asked_is_made_harbour(text: str, kinds: list[str]) -> None:
    frame = _harbour(text)
    assert [str(t.kind) for t in frame.tasks] == kinds, frame
    assert all(t.owner == "may" for t in frame.tasks), frame


def test_a_product_made_from_nothing_is_still_asked_about() -> None:
    frame = _default("copy my document and a coffee")
    assert frame.tasks == [] and (frame.question or "").startswith("Shall I copy your document")
