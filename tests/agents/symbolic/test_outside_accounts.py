"""A send to an outside personal account the assistant has no channel to (blind rounds 20 to
22's class, on a conservation department no sentence was written for,
``helpers.conservation_lab``): "send Joss's timesheet to my personal gmail please" is declined
in words (only colleagues here can be sent files); on main Joss's file was handed to the
requester as if "to me". A send to a colleague, or to the requester here, is done as before."""

from __future__ import annotations

import pytest

from helpers.conservation_lab import conservation_lab
from helpers.reading import frame_reader

_frame = frame_reader(conservation_lab, "nell")


@pytest.mark.parametrize(
    "text",
    [
        "send Joss's timesheet to my personal gmail please",
        "send Joss's timesheet to my personal email",
        "forward Bea's timesheet to my hotmail",
        "can you email my timesheet to my home address",
        "send Joss's timesheet to my gmail account",
        "could you send Otto's timesheet to nell.archer@example.org",
        "send my timesheet to my private inbox please",
    ],
)
def test_a_send_to_an_outside_account_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    said = frame.decline or frame.question or ""
    assert "outside" in said, frame


@pytest.mark.parametrize(
    ("text", "owner", "recipient"),
    [
        ("send Joss's timesheet to me", "joss", "nell"),
        ("send Joss's timesheet to Bea", "joss", "bea"),
        ("send Joss's timesheet to my email", "joss", "nell"),
    ],
)
def test_a_send_to_someone_here_is_done(text: str, owner: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "timesheet", owner, recipient)
    ], frame
