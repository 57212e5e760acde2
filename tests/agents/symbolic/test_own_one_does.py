"""What the speaker's own thing does, said after a request with a plain verb that ends the
clause ("Can I borrow Frank's headphones? Mine just crackle.", "my scissors just squeak"), is
told: the reason for borrowing, never a second thing asked for (it asked "who should get your
headphones?", or where the speaker's own scissors were). Found in a blind round's radio
station; analogues here on the default office."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import load_office


@functools.cache
def _default() -> InstructionParser:
    return InstructionParser(load_office())


@pytest.mark.parametrize(
    "text",
    [
        "Can I borrow Wang's scissors? Mine just crackle.",
        "can I borrow Wang's scissors? my scissors just squeak",
        "could I borrow Wang's scissors, mine just stick",
        "Can I borrow Wang's stapler? Mine just jams.",
    ],
)
def test_what_the_own_one_does_is_the_reason(text: str) -> None:
    frame = _default().parse(text, "zhang")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", text.split("Wang's ")[1].split()[0].strip("?,"), "wang", "zhang")
    ]
    assert frame.question is None


@pytest.mark.parametrize(
    "text",
    [
        # near-misses: the speaker's own one asked for, or said with no verb
        "bring me mine",
        "mine please",
        "mine pls",
    ],
)
def test_the_own_one_asked_for_is_not_told(text: str) -> None:
    frame = _default().parse(text, "zhang")
    assert not any(e.meaning == "a statement, context only" for e in frame.evidence)
