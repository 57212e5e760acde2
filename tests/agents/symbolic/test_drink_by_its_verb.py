"""How a drink is taken, said beside the verb of the office's service that makes it ("Brew
please. Milk, no sugar."), describes the drink: milk is never fetched for it (blind round
43-44's class F2, in part: milk was brought from the fridge). The bare verb with no drink named
is still not read as the drink here: it is asked about, in words. A plain ask for milk still
fetches milk."""

from __future__ import annotations

import pytest

from helpers.nursery_yard import nursery_yard
from helpers.reading import frame_reader

_frame = frame_reader(nursery_yard, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "Brew please. Milk, no sugar.",
        "brew me one pls, milk and one sugar",
        "Brew pls, white, two sugars",
    ],
)
def test_how_the_drink_is_taken_is_never_milk_to_fetch(text: str) -> None:
    frame = _frame(text)
    assert not any(t.item == "milk" for t in frame.tasks), frame
    assert any("how they take" in e.meaning for e in frame.evidence), frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("can you bring me some milk from the fridge", [("transfer", "milk", "ada")]),
        ("tea please, milk no sugar", [("produce", "tea", "ada")]),
        ("cuppa pls, white one sugar", [("produce", "tea", "ada")]),
    ],
)
def test_near_misses_keep_their_reading(text: str, tasks: list[tuple[str, str, str]]) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == tasks, frame
