"""Complaints and remarks that name an operation's or an item's word are told, not asked: a
mess said with "all over" or "everywhere" ("red wax all over the floor" where waxing is a
service), a remark on the day ("lovely day to eat lunch outside" where lunch is an item) and a
state said with an adverb in its "'s" ("the sun's finally out") are answered in words and move
nothing. A request beside them, or the service asked for, reads as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import frame_reader
from helpers.verb_names import verb_names


@functools.cache
def _default() -> Office:
    return load_office(DEFAULT_FILE)


_frame = frame_reader(_default, "lee")
_waxing = frame_reader(verb_names, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "the wax station's leaking again, red wax all over the floor",
        "red wax all over the floor again",
        "the wax station's playing up, red wax everywhere",
        "drawing tube all over the floor",
    ],
)
def test_a_mess_told_is_words(text: str) -> None:
    frame = _waxing(text)
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    "text",
    [
        "sun's finally out, lovely day to eat lunch outside",
        "lovely day to eat lunch outside",
        "the sun's finally out, lovely day for lunch in the park",
        "such a grim morning for lunch at the desk",
        "oh, beautiful weather to eat my lunch outside",
    ],
)
def test_a_remark_on_the_day_is_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("my lunch is in the fridge, bring it to me", "lunch"),
        ("lovely day. Could you bring me my lunch?", "lunch"),
        ("nice day, bring my lunch to me please", "lunch"),
        ("it's a grim morning, could you bring me the stapler", "stapler"),
    ],
)
def test_a_request_beside_a_remark_still_runs(text: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "lee")]


def test_the_service_asked_for_is_still_asked() -> None:
    frame = _waxing("wax my tube please")
    assert frame.decline is None, frame
    assert frame.tasks or frame.question, frame


def test_a_state_with_an_adverb_is_still_a_statement() -> None:
    frame = _frame("the printer's still jammed")
    assert frame.tasks == [] and frame.question is None, frame
