""" "no more X for me", "no X for me today": "no" before a quantity of a thing declines it, so
nothing is offered, made or moved. Before, "no more water for me thanks" made water and "no
more coffee for me today, I'm shaking" offered a coffee. A "no" of how a thing is taken ("no
milk in my coffee please") and "one more" / "more X please" still ask."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_mao = frame_reader(default_office, "mao")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_mao, "no more water for me thanks"),
        (_mao, "no more coffee for me today, I'm shaking 😅"),
        (_mao, "no coffee for me today"),
        (_mao, "no more tea for me"),  # nothing here makes tea: still declined, not asked
        (_mao, "I've had enough coffee"),
        (_may, "no more tea for me thanks"),
        (_may, "no tea for me today, ta"),
        (_may, "no more notepads for us"),
    ],
)
def test_declining_more_moves_and_offers_nothing(read: ReadFrame, text: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None


@pytest.mark.parametrize(
    ("read", "text", "item", "who"),
    [
        (_mao, "more coffee please", "coffee", "mao"),
        (_mao, "one more coffee for me please", "coffee", "mao"),
        (_mao, "no milk in my coffee please", "coffee", "mao"),
        (_mao, "no more coffee for me, can I have some water?", "water", "mao"),
        (_may, "one more tea please", "tea", "may"),
    ],
)
def test_asking_for_more_or_how_it_is_taken_still_makes_it(
    read: ReadFrame, text: str, item: str, who: str
) -> None:
    frame = read(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, who)], frame


def test_a_request_with_no_rush_is_unchanged() -> None:
    frame = _mao("bring me a pen, no rush")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("pen", "mao")], frame
