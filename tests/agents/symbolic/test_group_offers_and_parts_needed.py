"""An offer to the office at large and a thing said to need a part are no requests
(reading/offers.py, reading/thing_needs.py part_told).

"would anyone like a coffee?" made a coffee for the speaker: a question to colleagues, most
likely sent to the wrong chat, is now met with "Shall I ...?" and moves nothing. "the
calculator needs new batteries" fetched a calculator: a thing said to need a part or supply
the office does not keep is how the thing is, a statement. Wanting with an infinitive ("would
anyone like to bring me a coffee?"), a request to lend ("can anyone lend me ..."), work the
office does ("the document needs a stamp") and the speaker's own need are read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_default, "would anyone like a coffee?"),
        (_default, "does anybody want some water?"),
        (_default, "anyone fancy a coffee?"),
        (_harbour, "would anyone like a tea?"),
        (_harbour, "would everyone like a notepad?"),
        (_harbour, "does somebody want a highlighter?"),
    ],
)
def test_an_offer_to_the_office_moves_nothing(read: ReadFrame, text: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Shall I" in frame.question


@pytest.mark.parametrize(
    ("read", "text", "item", "who"),
    [
        (_default, "would anyone like to bring me a coffee?", "coffee", "lee"),
        (_default, "would you like to bring me a coffee?", "coffee", "lee"),
        (_default, "can anyone lend me a stapler?", "stapler", "lee"),
        (_harbour, "would anyone like to bring me a tea?", "tea", "rose"),
        (_harbour, "could someone bring me a ruler?", "ruler", "rose"),
    ],
)
def test_a_request_to_anyone_is_still_a_request(
    read: ReadFrame, text: str, item: str, who: str
) -> None:
    frame = read(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, who)], frame


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_harbour, "the calculator needs new batteries"),
        (_harbour, "my calculator needs a new battery"),
        (_harbour, "the umbrella needs a new spoke"),
        (_harbour, "calculator needs batteries"),
        (_default, "the stapler needs staples"),
        (_default, "my pen needs fresh ink"),
        (_default, "the stapler needs refilling"),
    ],
)
def test_a_part_a_thing_needs_is_told_never_the_thing_fetched(read: ReadFrame, text: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.question is None, frame


def test_work_the_office_does_is_still_asked_for() -> None:
    frame = _default("the document needs a stamp")
    assert [t.item for t in frame.tasks] == ["document"], frame
