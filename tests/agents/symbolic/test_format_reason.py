"""A reason naming a format is not a second request (``reading.format_reason``): "scan my
document pls, the bank wants a pdf" asked whom the document goes to (the bank's want read as
a pdf passed back to the requester, or the document handed on); someone outside the office
wanting the result in some form says why the work is asked. A colleague's want, the
speaker's own, and a second part said with its own verb are read as before."""

from __future__ import annotations

import functools

import pytest
from _offices import understood_tasks

from assistantx.agents.symbolic.reading.format_reason import without_format_reasons
from assistantx.core.office import Office
from assistantx.evaluation import metrics
from helpers.dataset_offices import default_office_that_scans, harbour_office
from helpers.one_episode import ppdr_episode
from helpers.reading import frame_reader


@functools.cache
def scans_to_pdf() -> Office:
    """The default office whose printer also scans a paper to a PDF (an electronic ``scan``)."""
    return default_office_that_scans("scan", {"id": "scan", "name": "scanned pdf"})


_HARBOUR = frame_reader(harbour_office, "will")
_SCANS = frame_reader(scans_to_pdf, "lin")

Read = tuple[str, str | None, str | None, str]  # kind, item, owner, recipient


def _tasks(frame: object) -> list[Read]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in getattr(frame, "tasks", [])]


@pytest.mark.parametrize(
    "text",
    [
        "scan my document pls, the bank wants a pdf",
        "scan my form, HR want it emailed",
        "scan my contract, accounts want a copy",
        "scan my invoice as the council needs it emailed",
        "scan my timesheet please. The agency only accepts a pdf",
    ],
)
def test_harbour_the_reason_is_no_part(text: str) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("copy", "document", "will", "will")], frame


@pytest.mark.parametrize(
    "text",
    [
        "scan my document pls, the bank wants a pdf",
        "scan my form, HR want it emailed",
        "scan my contract - the landlord needs a soft copy",
    ],
)
def test_scan_to_pdf_the_reason_is_no_part(text: str) -> None:
    frame = _SCANS(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("copy", "document", "lin", "lin")], frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # a second part with its own verb and a colleague: two parts, as before
        (
            "scan my document and email the pdf to Mark",
            [("copy", "document", "will", "will"), ("send_file", "file", "will", "mark")],
        ),
        # a colleague's want is a part of the request of its own, not a reason
        (
            "scan my document, Mark wants a pdf",
            [("transfer", "document", "will", "mark"), ("send_file", "file", "will", "mark")],
        ),
    ],
)
def test_harbour_a_part_stays(text: str, tasks: list[Read]) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == tasks, frame


@pytest.mark.parametrize(
    "text",
    [
        "the bank wants a pdf",  # said alone: nothing asked before it
        "scan my document, I need a pdf",  # the speaker's own want
        "scan my document, they want a pdf",  # whom "they" means is not known
        "print my file, Wang wants a copy",  # a colleague
    ],
)
def test_the_rewrite_leaves_wants_of_the_request(text: str) -> None:
    person_words = {"wang", "mark"}
    assert without_format_reasons(text, lambda w: w.lower() in person_words) == text


def test_the_rewrite_drops_the_reason() -> None:
    said = "scan my duty return pls, customs want a pdf"
    assert without_format_reasons(said, lambda w: False) == "scan my duty return pls"


@pytest.mark.parametrize(
    "text",
    [
        "could you print my spreadsheet and hand it to Manager Mao? he'd like it on paper",
        "print my spreadsheet for Mao, he wants a paper copy",
        "copy my report for Wang since she needs it on paper",
    ],
)
def test_the_want_of_the_one_served_is_the_reason(text: str) -> None:
    """The colleague the request already serves, named again by a pronoun wanting the
    result in some form: why it is asked, never a second errand (paper brought to the
    speaker was a wrong physical action)."""
    tasks = understood_tasks("default", "dang", text)
    assert len(tasks) == 1 and tasks[0][0] in ("print", "copy") and tasks[0][3] in ("mao", "wang")


@pytest.mark.parametrize(
    ("text", "kept"),
    [
        ("print my sheet, she wants it on paper", True),  # nobody named before: whose want?
        ("print my sheet for Mao, he wants it on paper", False),
    ],
)
def test_the_rewrite_drops_a_pronouns_want_only_after_a_person(text: str, kept: bool) -> None:
    said = without_format_reasons(text, lambda w: w.lower() == "mao")
    assert (said == text) is kept


async def test_the_scan_comes_back_to_the_requester() -> None:
    episode = await ppdr_episode(
        harbour_office(),
        "will",
        "scan my document pls, the bank wants a pdf",
        [{"holds": ["will", "document:will"]}, {"holds": ["will", "scan:will"]}],
    )
    assert metrics.success(episode), (episode.milestones, episode.trace.summary)
    assert metrics.wrong_handovers(episode) == []
