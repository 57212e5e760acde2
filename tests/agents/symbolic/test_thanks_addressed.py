"""A thanks said to a colleague by name ("cheers for the book, Yang!") is answered in words: the
name at the message's end (or start) is an address, so a name two colleagues share, a name
nobody has, or a name that is also a word is never asked about. A name inside a request beside
the thanks is still the request's, and still asked about where several colleagues share it."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "sun")
_harbour = frame_reader(harbour_office, "mark")


@pytest.mark.parametrize(
    "text",
    [
        "cheers for the book, Yang!",  # two colleagues answer to Yang
        "thanks for the stapler, Yang",
        "ta for the cable Wei!",
        "ta for the cable, Liu",
        "thanks for the pen, Lee and Yang",
        "thanks for the book, Bob!",  # nobody is called Bob
    ],
)
def test_a_thanks_to_a_name_is_words_in_the_default_office(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "welcome" in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "thanks for the ruler, Grace!",  # Grace is also a word
        "cheers for the umbrella, Joy and Hope",
        "ta for the tape, Dave",
        "Grace, thanks for the charger",
    ],
)
def test_a_thanks_to_a_name_is_words_in_harbour(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "welcome" in frame.decline, frame


def test_a_request_beside_the_thanks_still_asks_which_colleague() -> None:
    frame = _default("thanks, and can you bring Yang's stapler?")
    assert frame.tasks == [], frame
    assert frame.question is not None and "Who do you mean by 'Yang'" in frame.question, frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("thanks, and can you bring Grace's ruler?", "grace"),
        ("thanks for the charger, Grace, can you bring me Hope's ruler", "hope"),
    ],
)
def test_a_request_beside_the_thanks_is_done(text: str, owner: str) -> None:
    frame = _harbour(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "ruler", owner)], frame


def test_a_statement_said_to_a_name_is_still_words() -> None:
    frame = _default("Dang, I left my stapler at home")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame
