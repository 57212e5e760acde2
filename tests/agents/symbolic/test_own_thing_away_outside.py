"""Where the requester's own thing is, said beside a request ("can you borrow a stapler for
me, mine's at the repair shop"), is why they ask: a statement, never an errand outside the
office. "mine" opened the clause and, being a verb too ("to mine"), was taken for a command
to the robot with a shop after it; a word with a finite "is"/"has" right after it is a
subject (``screen.outside_place``). A command to go out is still declined."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lin")
_HARBOUR = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("read", "text", "item"),
    [
        (_DEFAULT, "can you borrow a stapler for me, mine's at the repair shop", "stapler"),
        (_DEFAULT, "can you lend me a pen? mine is at the shop", "pen"),
        (_DEFAULT, "get me some scissors pls, mine were at the menders last I saw", "scissors"),
        (_HARBOUR, "could I borrow an umbrella? mine's at the dry cleaners", "umbrella"),
        (_HARBOUR, "a charger please, mine has gone to the repair shop", "charger"),
    ],
)
def test_the_request_is_read_and_the_place_is_context(read: object, text: str, item: str) -> None:
    frame = read(text)  # type: ignore[operator]
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", item, None)], frame


@pytest.mark.parametrize(
    "text",
    [
        "drive over to the bank and get my cheque book",
        "pop down to the repair shop and collect my stapler",
    ],
)
def test_going_out_is_still_declined(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "outside the office" in frame.decline, frame
