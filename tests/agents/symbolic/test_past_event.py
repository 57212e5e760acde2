"""What already happened to the speaker's own thing, told beside a request ("need some
secateurs pls, mine went in the compost", "need a new folder, mine got shredded by mistake"),
is why the request is made: the service or waste container its words name is not asked for
(blind round 43's class: the compost was read as the request and declined). A request for
the service itself is read as before, and so is a request that points back to the event."""

from __future__ import annotations

import pytest

from helpers.potting_shed import potting_shed
from helpers.reading import frame_reader

_frame = frame_reader(potting_shed, "ivo")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("need some secateurs pls, mine went in the compost", "secateurs"),
        ("need secateurs, my old pair went in the compost heap", "secateurs"),
        ("could I get some pruners? mine went in the compost", "secateurs"),
        ("need a new folder, mine got shredded by mistake", "folder"),
        ("can I get a folder? my old one has been shredded", "folder"),
        ("need a new folder, mine went through the laminator and melted", "folder"),
        ("my folder got shredded. bring me a folder please", "folder"),
    ],
)
def test_the_past_event_is_the_reason_not_the_request(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient, t.operation) for t in frame.tasks] == [
        ("transfer", item, "ivo", None)
    ], frame


@pytest.mark.parametrize(
    "text", ["mine went in the compost", "my trowel went in the compost", "mine got shredded"]
)
def test_the_event_alone_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "won't" not in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("could you compost my prunings", "compost"),
        ("compost my prunings please", "compost"),
        ("put my prunings in the compost", "compost"),
        ("chuck my prunings in the compost", "compost"),
        ("need some secateurs pls, mine went in the compost. and compost my prunings", "compost"),
    ],
)
def test_a_request_for_the_service_is_read_as_before(text: str, operation: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert operation in [t.operation for t in frame.tasks], frame


@pytest.mark.parametrize(
    "text",
    [
        "chuck Morwen's trowel in the skip",
        "put Morwen's prunings in the compost",
        "chuck Morwen's trowel in the compost",
    ],
)
def test_a_colleagues_thing_put_away_is_still_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame
    assert "Noted" not in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "my ledger needs the shredded paper on it",
        "my poster needs laminating",
        "my poster should get laminated, deal with it",
        "my ledger must be shredded before it goes out",
    ],
)
def test_a_present_need_of_ones_own_thing_is_no_past_event(text: str) -> None:
    frame = _frame(text)
    assert frame.evidence == [] or all("happened" not in e.meaning for e in frame.evidence), frame


def test_a_request_that_points_back_is_read_as_before() -> None:
    frame = _frame("my folder got shredded, can I have a new one")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "folder", "ivo")
    ], frame
