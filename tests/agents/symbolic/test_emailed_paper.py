"""A colleague's paper asked for, then to be sent electronically ("could I have Wang's report?
just email it to me"): never the paper carried over. Where an operation of the office makes
an electronic copy of that paper (a scan to PDF, a scanned copy), the copy is made, with the
owner's yes as any work on their paper; where none does, it is said and asked whether to
bring the paper, and only a yes brings it (``reading.emailed_paper``)."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.chambers_post import chambers_post
from helpers.dataset_offices import default_office, harbour_office
from helpers.drafting_office import drafting_office
from helpers.reading import answered_reader, frame_reader

_default = frame_reader(default_office, "lee")
_chambers = frame_reader(chambers_post, "nadia")
_chambers_answered = answered_reader(chambers_post, "nadia")
_harbour = frame_reader(harbour_office, "will")
_drafting = frame_reader(drafting_office, "odile")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "question"),
    [
        # an office that keeps no electronic files: said and asked (was the paper handed over)
        (
            "could I have Greta's brief? just email it to me",
            "I can't email a paper brief here. Shall I bring Greta's brief to you?",
        ),
        (
            "hi! could I have Greta's brief? message it over please",
            "I can't message a paper brief here. Shall I bring Greta's brief to you?",
        ),
        (
            "can you get me Greta's deed, and email it to me",
            "I can't email a paper brief here. Shall I bring Greta's deed to you?",
        ),
        # joined by "and", and the colleague said by "her" after the one asked
        (
            "can you get me Greta's deed and email it to me",
            "I can't email a paper brief here. Shall I bring Greta's deed to you?",
        ),
        (
            "ask Greta for her deed and email it to me",
            "I can't email a paper brief here. Shall I bring Greta Lund's deed to you?",
        ),
    ],
)
def test_no_electronic_file_or_copy_is_said_and_asked(text: str, question: str) -> None:
    frame = _chambers(text)
    assert frame.question == question, frame
    assert frame.tasks == []


def test_a_yes_brings_the_paper_a_no_does_nothing() -> None:
    text = "could I have Greta's brief? just email it to me"
    assert _tasks(_chambers_answered(text, ["Yes, please."])) == [
        ("transfer", "brief", "greta", "nadia")
    ]
    no = _chambers_answered(text, ["No, thanks."])
    assert no.tasks == [] and no.decline is not None


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the class's analogues: the default office's report is its paper and its file
        # ("email me Wang's report" is Wang's file); was Chen's paper fetched and carried
        (
            "hey could you get Chen Jie's report and send it to me",
            [("send_file", "file", "chen", "lee")],
        ),
        ("ask Wang for her report and email it to me", [("send_file", "file", "wang", "lee")]),
        # was asked whether to bring the paper
        (
            "could I have Wang's report? just email it to me",
            [("send_file", "file", "wang", "lee")],
        ),
        (
            "hi! could I have Wang's report? message it over please",
            [("send_file", "file", "wang", "lee")],
        ),
        (
            "can you get me Zhang's contract, and email it to me",
            [("send_file", "file", "zhang", "lee")],
        ),
        (
            "get Chen Jie's report and then forward it to Wang",
            [("send_file", "file", "chen", "wang")],
        ),
        # must not change: the file asked for at once, and the paper brought
        ("email me Wang's report", [("send_file", "file", "wang", "lee")]),
        (
            "hey could you get Chen Jie's report and bring it to me",
            [("transfer", "document", "chen", "lee")],
        ),
        ("ask Wang for her report and bring it to me", [("transfer", "document", "wang", "lee")]),
    ],
)
def test_default_office_the_paper_sent_is_its_file(
    text: str, expected: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    frame = _default(text)
    assert frame.question is None and _tasks(frame) == expected, frame


@pytest.mark.parametrize(
    ("read", "text", "expected"),
    [
        # harbour's scanner makes a "scanned copy" of a document
        (
            "harbour",
            "could I have Pat's contract? just email it to me",
            [("copy", "document", "pat", "will")],
        ),
        (
            "harbour",
            "can I get Bill's invoice? send it over",
            [("copy", "document", "bill", "will")],
        ),
        # a scanner that makes a PDF of a certificate
        (
            "drafting",
            "could I have Piet's certificate? just email it to me",
            [("copy", "certificate", "piet", "odile")],
        ),
        (
            "drafting",
            "can I get Ezra's permit? email it over",
            [("copy", "certificate", "ezra", "odile")],
        ),
    ],
)
def test_an_office_that_makes_an_electronic_copy_makes_it(
    read: str, text: str, expected: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    frame = {"harbour": _harbour, "drafting": _drafting}[read](text)
    assert frame.question is None and _tasks(frame) == expected, frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # an electronic thing: forwarded as before
        ("email me Wang's spreadsheet", [("send_file", "file", "wang", "lee")]),
        # the paper asked for with no channel: brought as before
        ("bring me Wang's report", [("transfer", "document", "wang", "lee")]),
        # no paper: the stapler is no thing to email; read as before
        (
            "could I have Wang's stapler? just email it to me",
            [("transfer", "stapler", "wang", "lee")],
        ),
        # a described file: sent as before
        (
            "could I have Wang's budget plan? just send me the file",
            [("send_file", "file", "wang", "lee")],
        ),
    ],
)
def test_must_not_change_neighbours(
    text: str, expected: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    frame = _default(text)
    assert frame.question is None and _tasks(frame) == expected, frame


def test_a_colleague_named_as_whom_it_is_emailed_to_is_kept() -> None:
    # was Greta's paper carried to Tomas; now said, and a yes brings it to Tomas
    text = "could I have Greta's brief? email it to Tomas"
    question = "I can't email a paper brief here. Shall I bring Greta's brief to Tomas Berg?"
    assert _chambers(text).question == question
    assert _tasks(_chambers_answered(text, ["Yes, please."])) == [
        ("transfer", "brief", "greta", "tomas")
    ]
    # an office that keeps the paper's file: that file, for the one named
    assert _tasks(_default("could I have Wang's report? email it to Zhang")) == [
        ("send_file", "file", "wang", "zhang")
    ]
    # an office that scans it: the copy for the one named
    assert _tasks(_harbour("could I have Pat's contract? email it to Bill")) == [
        ("copy", "document", "pat", "bill")
    ]
