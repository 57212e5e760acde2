"""A correction of the thing asked for ("could you bring me a coffee? sorry, make that a snack
from the vending machine, I've had 3 coffees already", "change that to a tea", "actually a
snack instead") replaces the thing and keeps the rest of the request (who gets it); a reason
after it that names the old thing is context (blind rounds 61-62's class: "OK, I've dropped
that request"). A withdrawal after "sorry" ("sorry, forget the coffee") still withdraws."""

from __future__ import annotations

import pytest

from helpers.match_desk import match_desk
from helpers.reading import frame_reader

_frame = frame_reader(match_desk, "jeanluc")


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        (
            "could you bring me a coffee? sorry, make that a snack from the vending machine, "
            "I've had 3 coffees already",
            "snack",
            "jeanluc",
        ),
        ("bring Dara a coffee, sorry, make it a snack from the vending machine", "snack", "dara"),
        ("could you bring me a coffee? change that to a tea", "tea", "jeanluc"),
        ("bring Dara a coffee, actually a tea instead", "tea", "dara"),
        ("get me a coffee - actually, switch that for a snack, too much caffeine", "snack", None),
        ("bring me a coffee, sorry, make that a tea", "tea", "jeanluc"),
    ],
)
def test_a_corrected_thing_replaces_the_one_asked_for(
    text: str, item: str, recipient: str | None
) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [t.item for t in frame.tasks] == [item], frame
    assert [t.recipient for t in frame.tasks] == [recipient or "jeanluc"], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me a coffee, sorry, forget the coffee",
        "could you bring me a coffee? actually never mind",
        "bring me a coffee, sorry, cancel that",
    ],
)
def test_a_withdrawal_after_sorry_still_withdraws(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "dropped" in frame.decline, frame
