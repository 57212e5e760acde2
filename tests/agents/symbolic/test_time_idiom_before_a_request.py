"""An idiom of time said right before the request's modal with no comma ("when you get a sec
could you print my file for Wang ...") is set aside as it is with a comma (fix93e class 5:
it was read as a question about the meeting room, "As far as I know the meeting room ... is in
service"). The request that follows is read alone; with a comma, and without the idiom, it
reads as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "rose")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "when you get a sec could you print my file for Wang and drop it at the meeting room",
        "when you have a minute can you print my file for Wang",
        "when you get a sec, could you print my file for Wang",
        "could you print my file for Wang and drop it at the meeting room",
    ],
)
def test_the_print_for_wang_is_read_in_the_default_office(text: str) -> None:
    frame = _default(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("print", "lee", "wang")]


def test_a_fetch_after_the_idiom() -> None:
    frame = _default("whenever you've got a moment would you bring me a stapler")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "stapler", "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "when you get a chance could you print my report for Mark and drop it at reception",
        "could you print my report for Mark and drop it at reception",
    ],
)
def test_the_print_for_mark_is_read_in_harbour(text: str) -> None:
    frame = _harbour(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "mark")]
