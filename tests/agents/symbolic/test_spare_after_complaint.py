"""A thing named only in a complaint, then an ask for "a spare" that names no thing ("my
charger is dead. anyone got a spare?", "ran out of tape, anyone have some?") asks for one of
the kind complained of, for the speaker: anyone's (the owner asked as always) or the office's
supply, never the speaker's broken one (blind rounds 59-64's class: the thing was lost, the
ask answered "I don't know of any spare"). The complaint alone, a bare ask and an ask for
something else keep their readings: nothing moves."""

from __future__ import annotations

import pytest

from helpers.lamp_works import lamp_works
from helpers.reading import frame_reader

_frame = frame_reader(lamp_works, "odile")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("my charger is dead. anyone got a spare?", "charger"),
        ("my charger's dead. has anyone got a spare", "charger"),
        ("my charger is dead - any chance someone has one I could borrow?", "charger"),
        ("my stapler's jammed - does anybody have one I could use?", "stapler"),
        ("my stapler is jammed. anyone got a spare one?", "stapler"),
        ("ran out of tape, anyone have some?", "tape"),
        ("we're out of tape. anybody got some?", "tape"),
        ("my mouse died. got a spare one anywhere?", "mouse"),
        ("my torch is broken. does anyone have a spare I could use?", "torch"),
        # the complaint after the ask, said bare, or with words before its subject
        ("anyone got a spare? my charger just died", "charger"),
        ("charger's dead. anyone got a spare?", "charger"),
        ("ugh, my charger has died. does anyone have a spare?", "charger"),
        ("I lost my charger. anyone got a spare?", "charger"),
    ],
)
def test_a_spare_asked_after_a_complaint_is_one_of_that_kind(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "odile")]
    assert frame.tasks[0].owner != "odile", frame


@pytest.mark.parametrize(
    "text",
    [
        "my charger is dead.",
        "my charger is dead. anyone got a minute?",
        "anyone got a spare?",
        "my mouse died",
    ],
)
def test_without_both_halves_nothing_moves(text: str) -> None:
    assert _frame(text).tasks == []


@pytest.mark.parametrize(
    "text",
    [
        "my charger is dead, could someone bring me a spare",
        "anyone got a spare charger? mine's dead",
    ],
)
def test_the_noun_said_or_a_request_read_as_before(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "charger", "odile")
    ], frame


@pytest.mark.parametrize("text", ["anyone got a spare?", "anyone have some?"])
def test_a_bare_ask_for_a_spare_asks_back_in_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "Which item do you need a spare of?" in frame.decline


def test_a_colleagues_complaint_asks_no_spare_for_them() -> None:
    frame = _frame("Ginger's charger is dead. anyone got a spare?")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "Which item" not in frame.decline
