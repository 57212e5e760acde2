"""A part noun that is the office's name of another paper heads the phrase: "photocopy my
spreadsheet form" where "spreadsheet" is the office's electronic file and "form" its paper.
The head (the paper) is the thing; the earlier name says what it is about, so the paper
service asked (copy, scan) takes it. A part noun naming the same paper ("my contract form"),
a name alone ("print my spreadsheet") and "the spreadsheet" with a paper service keep their
reading."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "mao")
_HARBOUR = frame_reader(harbour_office, "bill")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "photocopy my spreadsheet form, ta",
        "photocopy my slides form please",
        "could you photocopy my pdf form",
    ],
)
def test_default_office_the_paper_head_is_copied(text: str) -> None:
    frame = _DEFAULT(text)
    assert _tasks(frame) == [("copy", "document", "mao")], frame


@pytest.mark.parametrize(
    "text",
    ["scan my draft form, ta", "scan my deck form please", "could you scan my spreadsheet form"],
)
def test_harbour_the_paper_head_is_scanned(text: str) -> None:
    frame = _HARBOUR(text)
    assert _tasks(frame) == [("copy", "document", "bill")], frame


def test_the_file_alone_is_still_printed() -> None:
    assert _tasks(_DEFAULT("print my spreadsheet")) == [("print", "file", "mao")]
    assert _tasks(_HARBOUR("print my draft")) == [("print", "file", "bill")]


def test_the_file_alone_with_a_paper_service_is_still_asked() -> None:
    frame = _DEFAULT("photocopy the spreadsheet")
    assert not frame.tasks and frame.question is not None, frame


def test_a_part_noun_of_the_same_paper_stays_a_part() -> None:
    assert _tasks(_DEFAULT("photocopy my contract form")) == [("copy", "document", "mao")]
    frame = _DEFAULT("could you photocopy the consent form sheets")
    assert _tasks(frame) == [("copy", "document", "mao")], frame
