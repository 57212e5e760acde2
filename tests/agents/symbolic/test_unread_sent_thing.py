"""A colleague's thing asked to be sent on, in words the office has nowhere ("get Carmen's
physio notes forwarded to me", blind round 23): the part is asked about, never dropped while
the other part of the request is done and reported "Done" (16 tasks of round 23). A thing the
office names is read as before."""

from __future__ import annotations

import pytest

from helpers.outside_broadcast import outside_broadcast
from helpers.reading import frame_reader

_frame = frame_reader(outside_broadcast, "quill")


@pytest.mark.parametrize(
    "text",
    [
        "Could I borrow a headset and get Dov's edit notes forwarded to me?",
        "get Dov's shot list sent to me please",
        "can you lend me a headset and have Sandy's call times emailed over",
    ],
)
def test_the_unknown_thing_to_send_on_is_asked_about(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame  # nothing done, nothing reported "Done"
    assert frame.question is not None and "not sure what" in frame.question


def test_a_thing_the_office_names_is_sent_on() -> None:
    frame = _frame("Could I borrow a headset and get Dov's rundown forwarded to me?")
    assert frame.question is None, frame
    assert ("send_file", "rundown", "quill") in [(t.kind, t.item, t.recipient) for t in frame.tasks]
