"""A colleague's seal asked for while they are out, to stamp or sign with, is their tool used
behind their back: declined in words, nothing moved, nobody asked to stamp. Their own
stamping, a plain transfer and a seal said without an absence keep their readings."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "take Wang's seal from her desk while she's out, I only need to stamp one thing",
        "grab Wang's seal while she's at lunch, I just need to stamp my form",
        "use Zhang's seal whilst he's in the meeting to stamp my contract",
        "could you fetch her seal while she's out? Wang won't need it, I'll stamp my form",
        "bring me Chen's seal while he is out so I can seal my invoice",
    ],
)
def test_an_absent_colleagues_seal_for_own_stamping_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "seal" in frame.decline and "I did nothing" in frame.decline


@pytest.mark.parametrize(
    ("text", "kind", "actor"),
    [
        ("can Wang stamp my form while she's at her desk?", "seal", "wang"),
        ("could Zhang stamp my contract with his seal?", "seal", "zhang"),
    ],
)
def test_their_own_stamping_stays_a_seal_task(text: str, kind: str, actor: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.actor) for t in frame.tasks] == [(kind, actor)], frame


def test_a_plain_transfer_while_they_are_out_still_asks_the_owner() -> None:
    frame = _frame("take Wang's stapler from her desk while she's out")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "wang", "lee")]


def test_their_seal_asked_for_while_they_are_out_without_stamping_still_asks_them() -> None:
    frame = _frame("take Wang's seal from her desk while she's out")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("seal", "wang", "lee")]
