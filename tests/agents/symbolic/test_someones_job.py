"""An obligation on nobody named beside a facility's report ("printer's out of toner,
someone's gonna have to ring the engineer") is a remark: the report is answered in words and
nothing moves (it was met with "I'm not sure what you need": blind round 86's class; the
sentences here are the tests' own). The same words for the speaker, or with an errand of the
office, keep their request."""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.core.office import Office, load_office
from helpers.reading import frame_reader

_HARBOUR = Path(__file__).parents[3] / "dataset" / "offices" / "harbour" / "office.yaml"


def _harbour() -> Office:
    return load_office(_HARBOUR)


_default = frame_reader(load_office, "mao")
_harbour_frame = frame_reader(_harbour, "mark")


@pytest.mark.parametrize(
    ("text", "report"),
    [
        (
            "printer's out of toner, someone's gonna have to ring the engineer",
            "the printer is out of toner",
        ),
        ("printer's out of paper, somebody needs to sort it out", "the printer is out of paper"),
        (
            "the coffee machine's out of beans, someone is going to have to phone the supplier",
            "the coffee machine is out of beans",
        ),
        ("the printer is jammed again, someone will have to call IT", "the printer is jammed"),
    ],
)
def test_the_report_is_answered_and_nothing_moves(text: str, report: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and report in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "report"),
    [
        (
            "the printer's out of toner, somebody will have to call the engineer",
            "the printer is out of toner",
        ),
        ("kettle's out of water, someone should sort it", "the kettle is out of water"),
    ],
)
def test_harbour_reports_the_same(text: str, report: str) -> None:
    frame = _harbour_frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and report in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "the printer's out of paper, can you bring me some paper",
        "printer's out of paper, someone should bring me some paper",
    ],
)
def test_a_request_for_the_speaker_is_fetched(text: str) -> None:
    assert [(t.kind, t.item, t.recipient) for t in _default(text).tasks] == [
        ("transfer", "paper", "mao")
    ]


def test_an_errand_for_a_colleague_is_still_done() -> None:
    assert [(t.item, t.recipient) for t in _default("someone needs to get Wang a pen").tasks] == [
        ("pen", "wang")
    ]


def test_a_person_out_of_paper_is_no_facility_report() -> None:
    frame = _default("Wang is out of paper")
    assert frame.tasks == [], frame
    assert "Thanks for letting me know" not in (frame.decline or ""), frame
