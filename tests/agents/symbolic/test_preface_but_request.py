"""A hedging preface ending in "but" before a request (round 201's class): "i hope mark wont
mind but can i borrow his ruler for the meeting" asks for Mark's ruler (on main the whole was
one told sentence: "Noted."); the preface is context, and its lower-case "mark", the subject
of the clause after "hope" (a finite verb after it), is the colleague "his" means. A preface
with no ask after "but" is still told."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    "text",
    [
        "i hope mark wont mind but can i borrow his ruler for the meeting",
        "i know mark is busy but can you bring me his ruler",
        "I know Mark is busy but could you bring me his ruler",
    ],
)
def test_harbour_preface_then_request(text: str) -> None:
    frame = _HARBOUR(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("ruler", "mark", "may")]


@pytest.mark.parametrize(
    "text",
    [
        "I hope Wang won't mind but can I borrow her stapler",
        "I know Wang is busy but could you bring me her stapler",
        "I hope Wang won't mind but could you bring me her stapler",
    ],
)
def test_default_preface_then_request(text: str) -> None:
    frame = _DEFAULT(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "wang", "lee")]


def test_default_preface_then_a_plain_one() -> None:
    frame = _DEFAULT("sorry to bother you but could I have a water")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("water", "lee")], frame


def test_harbour_told_hope_without_an_ask_stays_words() -> None:
    frame = _HARBOUR("i hope mark is feeling better but the meeting went fine")
    assert frame.tasks == [] and frame.question is None, frame
