"""A thing of the office that needs another, the other asked for by a stand-in ("the DI box
needs a fresh 9V battery, could you fetch me one?"): only the battery is fetched, for whoever
the ask names. The DI box had been fetched as well. A colleague's need ("Wang needs a
stapler, bring her one") and both things asked for plainly are read as before."""

from __future__ import annotations

import pytest
from _gear_office import read_as_lee


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("The DI box needs a fresh 9V battery, could you fetch me one?", "battery", "lee"),
        ("my DI box needs a fresh 9V battery, could you fetch me one?", "battery", "lee"),
        ("the printer needs paper, can you grab some", "paper", "lee"),
        ("the drill needs a battery. can you fetch one for me", "battery", "lee"),
        ("the drill needs a battery, could you bring Wang one?", "battery", "wang"),
    ],
)
def test_only_what_the_thing_needs_is_fetched(text: str, item: str, recipient: str) -> None:
    frame = read_as_lee(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", item, recipient)
    ], frame


def test_a_colleagues_need_goes_to_the_colleague() -> None:
    frame = read_as_lee("Wang needs a stapler, bring her one")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("stapler", "wang")], frame


def test_both_things_asked_for_are_both_fetched() -> None:
    frame = read_as_lee("bring me the DI box and a battery")
    assert sorted(t.item for t in frame.tasks if t.item) == ["battery", "di_box"], frame
