"""A word for an outsider right before one of the office's items names the item, not a
recipient (blind round 20 after its fixes: "send my guest package to Marcus and get Holly to
sign my form" asked who "my guest" was, and the task failed). "my guest rundown" is the
rundown; "to the guest" and "give the visitor my rundown" are still outsiders, offered to the
requester instead."""

from __future__ import annotations

import pytest

from helpers.outside_broadcast import outside_broadcast
from helpers.reading import frame_reader

_frame = frame_reader(outside_broadcast, "quill")


@pytest.mark.parametrize(
    "text",
    [
        "send my guest rundown to Dov",
        "forward my visitor rundown to Dov please",
        "send my guest rundown to Dov and get Renée to sign my call sheet",
    ],
)
def test_the_outsider_word_modifies_the_item(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert ("send_file", "rundown", "dov") in [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text", ["send my rundown to the guest please", "give the visitor my call sheet"]
)
def test_an_outsider_recipient_is_still_offered_to_the_requester(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None
    assert "hand things only to people of this office" in frame.question
