"""Issue #23, fixer fix143b class 4: "Could you print the invoice spreadsheet I sent and take it
to Grant?" asked what to do with the electronic file (the past "sent" read as the office's send
service). A relative clause "I sent / I emailed / I shared (you)" after a noun of a file makes
it the requester's own file ("my spreadsheet"); after a colleague ("the file Wang sent") it is
that colleague's, asked of them as before (``sent_file``). A noun the office does not know at
all is a file so sent; one of its other items ("the document I sent") is left as said."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office
from helpers.brewhouse import brewhouse, brewhouse_that_couriers
from helpers.dataset_offices import default_office_that_sends_out, harbour_office
from helpers.reading import frame_reader


@functools.cache
def _faxing() -> Office:
    # the default office whose printer also faxes a document, asked as "send"
    return default_office_that_sends_out("fax", "fax", "send", "the fax number")


_fax = frame_reader(_faxing, "mao")
_brew = frame_reader(brewhouse_that_couriers, "ines")
_labels = frame_reader(brewhouse, "ines")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        # the class's analogues
        ("could you print the spreadsheet I sent and take it to Wang", "wang"),
        ("Could you print the invoice spreadsheet I sent and take it to Wang?", "wang"),
        ("print the slides I emailed you", "mao"),
        # variants of our own
        ("could you print the budget slides that I shared with you earlier", "mao"),
        ("print the pdf I just forwarded and drop it with Zhou", "zhou"),
    ],
)
def test_the_file_i_sent_is_my_own(text: str, recipient: str) -> None:
    frame = _fax(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", "file", "mao", recipient)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Could you print the invoice spreadsheet I sent and take it to Bram?",
        "could you print the price workbook I sent over and take it to Bram",
    ],
)
def test_a_noun_the_office_does_not_know_sent_by_me_is_my_file(text: str) -> None:
    # "spreadsheet" and "workbook" are no word of this brewery's; the file goes to Bram
    frame = _brew(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", "file", "ines", "bram")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "pls run off the can labels for the sour, artwork is the file i sent",
        "run off the labels for the jars, artwork is the file I sent",
    ],
)
def test_labels_are_run_off_from_the_file_i_sent(text: str) -> None:
    frame = _labels(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", "file", "ines", "ines")
    ], frame


def test_harbour_deck_i_emailed() -> None:
    frame = _harbour("print the deck I emailed you and take it to Mark")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("file", "will", "mark")]


def test_the_file_a_colleague_sent_is_theirs() -> None:
    # neighbour: Wang's file, asked of Wang as any colleague's file
    frame = _fax("print the file Wang sent")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", "file", "wang", "mao")
    ], frame


def test_a_paper_i_sent_is_left_as_said() -> None:
    # neighbour: "the document I sent" is no file; not read as one
    frame = _fax("print the document I sent")
    assert not any(t.item == "file" for t in frame.tasks), frame
