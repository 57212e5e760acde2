"""A correction that says the request again for someone else replaces the recipient: "print my
file for me. actually, print it for Wang" prints it for Wang only; "and print one for Wang
too" adds a second (fix154a class 5, whose measured sentence "print the drill plan for me pls.
no wait, print it for Sam Whitlock, he's running it" printed for the speaker; the analogues
below already held on main when this was written, and are kept so they go on holding)."""

from __future__ import annotations

import pytest

from helpers.courier_room import courier_room
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")
_courier = frame_reader(courier_room, "ana")


@pytest.mark.parametrize(
    ("read", "text", "task"),
    [
        (_default, "print my file for me. actually, print it for Wang", ("print", "file", "wang")),
        (
            _default,
            "print my file for me pls. no wait, print it for Wang Fang, she's presenting it",
            ("print", "file", "wang"),
        ),
        (
            _default,
            "bring me the stapler - no wait, bring it to Zhang",
            ("transfer", "stapler", "zhang"),
        ),
        (
            _harbour,
            "print my file for me pls. sorry, print it for Mark, he's chairing",
            ("print", "file", "mark"),
        ),
        (
            _harbour,
            "print the document for me pls. no wait, print it for Will, he's running it",
            ("print", "file", "will"),
        ),
        (
            _courier,
            "print the agenda for me pls. no wait, print it for Kit Moran, he's running it",
            ("copy", "document", "kit"),
        ),
    ],
)
def test_the_corrected_recipient_alone_gets_it(
    read: ReadFrame, text: str, task: tuple[str, str, str]
) -> None:
    frame = read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [task]


def test_one_more_for_someone_else_is_two() -> None:
    frame = _default("print my file for me. and print one for Wang too")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "lee"), ("print", "wang")]
