"""Blind round 18, class 5: a send-out's destination said only as a description of the kind of
place the service asks for ("send my biopsy off to the outside lab", where the service asks
"which lab") names no place: it is asked, never sent to "the outside lab"; a named place is
still taken (``destination.only_describes``, on ``helpers.histology_lab``; the round's own
office and sentences were never read)."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.histology_lab import histology_lab
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(histology_lab, "bea")
_answered = answered_reader(histology_lab, "bea")


def _sent(frame: TaskFrame) -> list[tuple[str | None, str | None, str | None]]:
    return [(t.item, t.operation, t.destination) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "send my biopsy off to the outside lab pls",
        "send my biopsy off to an external lab",
        "can you send off my sample to the lab",
        "send my sample off to the other lab please",
    ],
)
def test_a_described_lab_is_asked_which(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None and "Where should I send it off to?" in frame.question


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("can you send off my sample to Northgate Diagnostics", "Northgate Diagnostics"),
        ("send my biopsy off to the lab at Northgate", "the lab at Northgate"),
        ("can you send my miniprep for sequencing to Source Bioscience", "Source Bioscience"),
    ],
)
def test_a_named_place_is_still_the_destination(text: str, place: str) -> None:
    assert [d for _, _, d in _sent(_frame(text))] == [place]


def test_the_answer_to_which_lab_is_the_destination() -> None:
    frame = _answered("send my biopsy off to the outside lab pls", ["Northgate Diagnostics"])
    assert _sent(frame) == [("sample", "send_off", "Northgate Diagnostics")]


@pytest.mark.parametrize(
    "text",
    [
        "send my biopsy off to the outside lab, Northgate Diagnostics please",
        "send my biopsy off to the outside lab (Northgate Diagnostics)",
    ],
)
def test_the_name_said_after_the_description_is_the_destination(text: str) -> None:
    assert _sent(_frame(text)) == [("sample", "send_off", "Northgate Diagnostics")]


@pytest.mark.parametrize(
    "text",
    [
        "send my biopsy off to the outside lab, thanks",
        "send my biopsy off to the outside lab, Ivy please",
    ],
)
def test_no_name_after_the_description_still_asks(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None and "Where should I send it off to?" in frame.question
