"""A question of where a thing is kept, offering the places it might be (blind rounds 20 to
22's class, on a conservation department no sentence was written for,
``helpers.conservation_lab``, where a colleague is called Clay and clay is also kept): "where
do we keep the clay for the casting trial, workshop store or dry store?" is answered in words
(where the office keeps it, or that it is not known); on main the choices after the comma were
left as a request and "what do you need?" was asked. Nothing moves, nobody is asked about Clay
the colleague. A request that offers places to fetch from is still a request."""

from __future__ import annotations

import pytest

from helpers.conservation_lab import conservation_lab
from helpers.playschool import playschool
from helpers.reading import frame_reader

_frame = frame_reader(conservation_lab, "nell")


@pytest.mark.parametrize(
    ("text", "said"),
    [
        (
            "where do we keep the clay for the casting trial, workshop store or dry store?",
            "workshop store",
        ),
        ("where do we keep clay, workshop or basement?", "dry store"),
        ("where's the modelling clay kept, the workshop store or the dry store?", "workshop"),
        ("where do we keep the clay?", "dry store"),
        ("clay for the casting trial - where do we keep it, workshop store or dry store?", "dry"),
        ("where would I find the clay for the casting trial, workshop store or dry store?", "dry"),
        ("where's the clay for the casting trial kept - workshop store or dry store?", "dry"),
        ("where do we keep the Clay for the casting trial, workshop store or dry store?", "dry"),
        ("where do we keep the batteries, photo room or basement?", "at their desk"),
        ("where are the timesheets kept, records office or workshop?", "don't know"),
        ("where do we store the sample trays, cold store or workshop?", "cold store"),
    ],
)
def test_where_a_thing_is_kept_is_answered_in_words(text: str, said: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and said in frame.decline, frame
    assert "Clay Moreno" not in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "bring me some clay, workshop store or dry store",
        "can you bring me some clay? workshop store or dry store, whichever's nearer",
        "bring me some clay - where do we keep it anyway, workshop store or dry store?",
    ],
)
def test_a_request_naming_places_to_fetch_from_is_still_done(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "clay", "nell")]


def test_choices_after_a_question_of_its_own_are_no_request() -> None:
    frame = _frame("where's the clay? workshop store or dry store?")
    assert frame.tasks == [], frame
    assert "not sure what you need" not in (frame.question or ""), frame


def test_where_a_colleague_is_still_asks_nothing_of_them() -> None:
    frame = _frame("where's Clay, workshop or basement?")
    assert frame.tasks == [], frame


def test_the_thing_named_first_is_the_one_asked_about_in_another_office() -> None:
    frame = frame_reader(playschool, "ada")(
        "milk for the tea, where do we keep it, fridge or cupboard?"
    )
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "green room fridge" in frame.decline, frame
