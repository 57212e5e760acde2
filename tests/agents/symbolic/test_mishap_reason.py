"""A clause that tells what happened to a thing of the office ("coffee spilled all over my
keyboard", "water got on my notes") is the reason beside the request, not a second request:
"i need Lin Tao's wipes, coffee spilled all over my keyboard!!" made a coffee and never
fetched the wipes. Two things asked for stay two requests, and a thing said with its errand's
own verb keeps its reading."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("i need Lin Tao's wipes, coffee spilled all over my keyboard!!", "lin"),
        ("i need Lin's wipes. coffee spilled all over my desk", "lin"),
        ("could you get me Zheng's wipes? water leaked everywhere", "zheng"),
        ("need some wipes, water got on my notes", None),
        ("coffee spilled, i need wipes", None),
        ("i need Lin's wipes - coffee went all over my desk", "lin"),
        ("can I borrow Yang's wipes, my coffee went everywhere", "yang"),
    ],
)
def test_what_happened_is_the_reason_not_a_request(text: str, owner: str | None) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "wipes", owner, "lee")
    ], frame


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("I need wipes, and a coffee please", [("transfer", "wipes"), ("produce", "coffee")]),
        ("coffee please, water later", [("produce", "coffee"), ("produce", "water")]),
        ("coffee for Wang please", [("produce", "coffee")]),
    ],
)
def test_things_asked_for_keep_their_reading(text: str, kinds: list[tuple[str, str]]) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item) for t in frame.tasks] == kinds, frame
