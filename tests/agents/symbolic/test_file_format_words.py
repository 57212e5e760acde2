"""A paper said with a word of an electronic format, or with a verb that only moves files, is
the owner's electronic file (blind round 59-60 class 2; the round's own offices and sentences
were never read): "fwd my invoice pdf to Omar thx", where "invoice" is a name of the office's
paper bill and the office also keeps electronic files (whose names say no format), passes the
file on; the paper was carried to Omar. Where the office keeps no electronic files it says so
in words and carries nothing. "bring my invoice to Omar" is still the paper, and "print my
invoice pdf" still prints the file."""

from __future__ import annotations

import pytest

from helpers.lending_bench import lending_bench, paper_bench
from helpers.reading import frame_reader

_frame = frame_reader(lending_bench, "mira")
_paper = frame_reader(paper_bench, "mira")


@pytest.mark.parametrize(
    "text",
    [
        "fwd my invoice pdf to Omar thx",
        "can u fwd my invoice pdf to omar thx",
        "fwd my invoice to Omar",
        "fwd Omar my receipt pls",
        "send my invoice pdf to Omar",
        "send Omar the pdf of my invoice",
        "send my invoice as a pdf to Omar",
        "upload my invoice for Omar",
        "attach my invoice pdf for Omar",
        "e-mail my invoice to Omar",
        "email my bill as an attachment to Omar",
        "forward my receipt to Omar",
    ],
)
def test_the_file_is_passed_on(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "file", "mira", "omar")
    ], frame


@pytest.mark.parametrize(
    "text", ["bring my invoice to Omar", "take my receipt over to Omar", "give Omar my bill"]
)
def test_the_paper_is_carried(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "bill", "mira", "omar")
    ], frame


@pytest.mark.parametrize("text", ["print my invoice pdf", "print the pdf of my invoice"])
def test_printing_the_file(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("print", "file", "mira")], frame


def test_a_physical_thing_forwarded_is_carried() -> None:
    frame = _frame("forward my lamp to Bea")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "lamp", "bea")]


@pytest.mark.parametrize(
    "text", ["fwd my invoice pdf to Omar thx", "email my invoice to Omar", "fwd Omar my receipt"]
)
def test_no_files_here_is_said_in_words(text: str) -> None:
    frame = _paper(text)
    assert not frame.tasks and frame.decline is not None, frame
    assert "electronic files" in frame.decline and "Omar Reyes" in frame.decline, frame
    assert "omar" not in frame.decline, frame


def test_the_paper_is_still_carried_where_no_files_are_kept() -> None:
    frame = _paper("bring my invoice to Omar")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "bill", "omar")]
