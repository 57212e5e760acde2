"""Chat drops the "my" before a thing out of use ("stapler's broken", "controller is dead"):
the bare item with its condition asks for nothing by itself. It is the requester's own where
they have one (a hint, as "my stapler is broken" is), told as context otherwise; the question
or request beside it is read on its own ("stapler's broken, any scissors going spare?" is
about scissors; it fetched a stapler, a wrong physical action). A question about a supply the
office keeps for anyone is answered with where it is kept."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.kilnworks import kilnworks
from helpers.reading import frame_reader

_zhang = frame_reader(load_office, "zhang")  # Zhang owns a stapler, no scissors
_kit = frame_reader(kilnworks, "kit")


@pytest.mark.parametrize(
    "text",
    [
        "stapler's broken, any scissors going spare?",
        "stapler's broken. any scissors going spare?",
        "stapler is dead, anyone got scissors?",
    ],
)
def test_the_question_beside_a_bare_broken_item_is_about_its_own_item(text: str) -> None:
    frame = _zhang(text)
    assert frame.tasks == [], frame
    assert frame.question is not None and "scissors" in frame.question
    assert [(h.kind, h.person, h.item_type) for h in frame.hints] == [
        ("condition", "zhang", "stapler")
    ]


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("stapler's broken", "your stapler is out of use"),
        ("stapler is broken", "your stapler is out of use"),
        ("my stapler is broken", "your stapler is out of use"),
    ],
)
def test_a_bare_broken_item_alone_is_told_and_nothing_moves(text: str, said: str) -> None:
    frame = _zhang(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and said in frame.decline
    assert "requester" not in frame.decline  # the person reads "your", never our word


def test_an_item_the_requester_has_none_of_is_told_as_context() -> None:
    frame = _zhang("scissors are broken")
    assert frame.tasks == [] and frame.question is None and frame.hints == [], frame
    assert frame.decline is not None


@pytest.mark.parametrize(
    "text",
    [
        "stapler's broken, can you bring me another one?",
        "stapler's broken, can you bring me one?",
        "stapler please",
    ],
)
def test_a_request_beside_it_or_a_bare_ask_still_fetches(text: str) -> None:
    frame = _zhang(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [("stapler", "zhang")], frame


@pytest.mark.parametrize("text", ["anyone got a calculator?"])
def test_a_question_about_a_kept_supply_says_where_it_is_kept(text: str) -> None:
    frame = _kit(text)
    assert frame.tasks == [], frame
    assert frame.question is not None
    assert "store cupboard" in frame.question and frame.question.endswith("?")


def test_a_kept_supply_going_spare_is_wanted() -> None:
    # "going (spare)" of a thing the office keeps for anyone is the speaker's want of one
    # (fix103e, ``screen.supply_going``); it was answered with where it is kept and an offer
    frame = _kit("any calculators going spare?")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("calculator", "kit")], frame
