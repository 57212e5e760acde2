"""An indefinite owner's possessive with no noun after it ("someone else's", "anybody's"),
said after a statement about the speaker's own thing ("my cable's fraying"), names that
thing's type: one of a colleague's, as "another one" does. Before, "my cable's fraying, could I
borrow someone else's?" was answered "I'm not sure what you need"."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "zheng")
_HARBOUR = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("my cable's fraying, could I borrow someone else's?", "data_cable"),
        ("my stapler's jammed, can I borrow somebody else's", "stapler"),
        ("my pen died, anyone's will do", "pen"),
        ("my scissors are broken, could I use anybody else's?", "scissors"),
    ],
)
def test_default_someone_elses_is_the_type_of_the_thing_said(text: str, item: str) -> None:
    frame = _DEFAULT(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "zheng")]
    assert frame.tasks[0].owner != "zheng"  # never the speaker's own broken one


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("my calculator's broken, could I borrow someone else's?", "calculator"),
        ("my ruler snapped, anyone's will do", "ruler"),
    ],
)
def test_harbour_someone_elses_is_the_type_of_the_thing_said(text: str, item: str) -> None:
    frame = _HARBOUR(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "may")]
    assert frame.tasks[0].owner != "may"


def test_a_colleague_named_still_owns_it() -> None:
    """Neighbour: a named colleague's possessive is that colleague's thing, as before."""
    frame = _DEFAULT("my stapler's jammed, can I borrow Wang's?")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "stapler", "wang")]


def test_a_noun_after_the_possessive_is_that_noun() -> None:
    """Neighbour: "someone else's stapler" after a cable names the stapler, not the cable."""
    frame = _DEFAULT("my cable's fraying, can I borrow someone else's stapler")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")]
