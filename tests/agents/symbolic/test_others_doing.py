"""A colleague's own doing beside a request is context (fix135c, class 2): "Priya needs to
measure a carton. take her my tape measure pls" asked whose carton was meant, and "Zhang needs
to cut some paper, bring him my scissors" fetched paper too. What a colleague needs (has, wants)
to do that is no errand or service of the office is what they will work on with the thing the
request names; the doing's object is nothing to fetch (reading/screen/others_doing.py)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("Wang needs to staple a report. take him my stapler pls", ("stapler", "lee", "wang")),
        ("Zhang needs to cut some paper, bring him my scissors", ("scissors", "lee", "zhang")),
        (
            "Wang has to staple some documents, can you bring him my stapler",
            ("stapler", "lee", "wang"),
        ),
    ],
)
def test_the_colleagues_doing_is_context(text: str, task: tuple[str, str, str]) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        (
            "Hope wants to add up the invoices, bring her my calculator",
            ("calculator", "may", "hope"),
        ),
        ("Will needs to measure a carton. take him my ruler pls", ("ruler", "may", "will")),
    ],
)
def test_the_same_in_another_office(text: str, task: tuple[str, str, str]) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


def test_the_work_asked_on_the_thing_is_no_doing_of_theirs() -> None:
    # must not change: the report is the work's thing, asked about
    assert _default("Wang needs a report stapled, can you do it?").question == (
        "Whose document do you mean?"
    )


def test_a_request_naming_no_thing_of_its_own_reads_the_doings_object() -> None:
    # "it" is the report: nothing else is named to take, so the piece is read as before
    assert _default("Wang needs to staple a report. take it to him").question == (
        "Whose document do you mean?"
    )


def test_a_service_of_the_office_is_still_asked() -> None:
    frame = _default("Wang needs to print a report, bring him my file")
    assert ("print", "file", "lee", "wang") in [
        (t.kind, t.item, t.owner, t.recipient) for t in frame.tasks
    ], frame
