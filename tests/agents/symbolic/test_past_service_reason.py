"""A service of the office told in the past of the speaker's own thing is why they ask, not
news that what they asked for is had already.

"gloves from stores when you get a chance. shredded mine on a wire rope this morning" was read
as a withdrawal ("OK, I've dropped that request"): "shredded" is the office's shredding, and a
past task word said of "mine" read as "I have one already". A verbless "<thing> from <place>"
is the request; the past service on the speaker's own one (``screen.past_service_reason``)
says why a new one is wanted, unless the message asked for that same service before it."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader
from helpers.rigging_loft import rigging_loft

_loft = frame_reader(rigging_loft, "gale")
_harbour = frame_reader(harbour_office, "jack")
_default = frame_reader(default_office, "mao")


@pytest.mark.parametrize(
    ("read", "text", "task"),
    [
        (
            _loft,
            "gloves from stores when you get a chance. shredded mine on a wire rope this morning",
            ("transfer", "glove", "gale"),
        ),
        (
            _loft,
            "tape from the cupboard when you get a chance. ripped mine on the door this morning",
            ("transfer", "tape", "gale"),
        ),
        (
            _loft,
            "a ruler from the cupboard pls, snapped mine earlier",
            ("transfer", "ruler", "gale"),
        ),
        (
            _loft,
            "a ruler from the cupboard pls, laminated mine by mistake",
            ("transfer", "ruler", "gale"),
        ),
        (
            _loft,
            "tape from the cupboard pls, spliced mine into the rope",
            ("transfer", "tape", "gale"),
        ),
        (
            _harbour,
            "a notepad from the cupboard when you get a chance, laminated mine by mistake",
            ("produce", "notepad", "jack"),
        ),
        (
            _harbour,
            "a notepad from the cupboard pls. scanned mine into the bin this morning",
            ("produce", "notepad", "jack"),
        ),
        (
            _default,
            "a pen from the print room when you get a chance, photocopied mine by mistake",
            ("transfer", "pen", "mao"),
        ),
    ],
)
def test_a_past_service_on_ones_own_thing_is_the_reason(
    read: ReadFrame, text: str, task: tuple[str, str, str]
) -> None:
    frame = read(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [task]


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_loft, "never mind the tape, found mine"),
        (_harbour, "never mind the notepad, found mine"),
        # the same service asked before it: done already, so the request is dropped
        (_loft, "shred my old drafts. actually I shredded them already"),
    ],
)
def test_a_withdrawal_still_withdraws(read: ReadFrame, text: str) -> None:
    frame = read(text)
    assert frame.question is None, frame.question
    assert frame.tasks == []


def test_a_service_asked_for_is_still_asked() -> None:
    """Neighbour: "shred my old drafts" asks for the shredding of the speaker's drafts."""
    frame = _loft("shred my old drafts")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("draft", "gale")]
    assert frame.tasks[0].kind != "transfer"
