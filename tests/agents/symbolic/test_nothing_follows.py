"""A told state and what it rules out, "so no <thing>": "printer's down till tomorrow, so no
printing", "Wang's away till Friday fyi, so no signatures this week". The consequence asks
nothing: the message is answered in words and nothing moves; the service word after "no" is
never a service asked for (``screen.nothing_follows``). A request after the "so" is still
one."""

from __future__ import annotations

import pytest
from _offices import parser


def _told(office: str, text: str, requester: str) -> None:
    frame = parser(office).parse(text, requester)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline and frame.decline_outcome == "done", frame


@pytest.mark.parametrize(
    "text",
    [
        "printer's down till tomorrow, so no printing",
        "the microwave's broken, so no reheating today",
        "printer's down so no printing today",
        "Wang's away till Friday fyi, so no signatures this week",
        "Mao's off till Monday btw, so no copies this week",
        "the coffee machine is broken, so there's no coffee till Monday",
    ],
)
def test_what_a_state_rules_out_is_told_default(text: str) -> None:
    _told("default", text, "zhang")


@pytest.mark.parametrize(
    "text",
    [
        "Pat's off till Monday btw, so no laminating this week",
        "the laminator's down till Thursday, so no laminating",
        "the scanner is broken so no scans today",
    ],
)
def test_what_a_state_rules_out_is_told_harbour(text: str) -> None:
    _told("harbour", text, "may")


def test_a_request_after_the_so_is_still_asked() -> None:
    # must not change: "so can you ..." asks for something (here which thing is signed)
    frame = parser("default").parse(
        "Wang's away till Friday, so can you get Zhang to sign it instead?", "zhang"
    )
    assert frame.question is not None and frame.decline is None, frame


def test_a_request_after_the_state_is_still_done() -> None:
    # must not change: the state is context beside a request of its own
    frame = parser("default").parse(
        "printer's down till tomorrow, so no printing. bring me a pen", "zhang"
    )
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "pen", "zhang")]
