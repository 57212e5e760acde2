""" "he can have mine" after a request is an offer of the speaker's, told as the reason, not
news that what was asked for is had already (blind round 26's class): "take my scissors over
to Lin Tao? I lost the pair he lent me so he can have mine" takes Chen's scissors to Lin; on
main the "have mine" dropped the request. "I have one", "I've got mine now" still withdraw."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "chen")


@pytest.mark.parametrize(
    "text",
    [
        "Could you take my scissors over to Lin Tao? I lost the pair he lent me so he can have "
        "mine.",
        "take my scissors to Lin Tao please, he can have mine",
        "give my scissors to Lin Tao, he may have them for the week",
    ],
)
def test_leave_to_have_keeps_the_request(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "scissors", "chen", "lin")
    ], frame


@pytest.mark.parametrize(
    "text",
    ["bring me a pen. actually I have one", "bring me a pen. oh I've got mine now"],
)
def test_had_already_still_withdraws(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "did nothing" in frame.decline


@pytest.mark.parametrize(("writer", "recipient"), [("liu", "yang"), ("yang", "liu")])
def test_a_name_the_writer_shares_is_the_colleagues(writer: str, recipient: str) -> None:
    """Blind round 25's default-office case: Liu Yang's "send my spreadsheet to Yang" is
    for Yang Lei; it was asked "Liu Yang or Yang Lei?"."""
    frame = _frame("send my spreadsheet to Yang please, he asked for the numbers", writer)
    assert frame.question is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", writer, recipient)
    ], frame
