"""Blind rounds 23-24, class 2: "take the stopwatch over to Kasia", said by someone who has a
stopwatch of their own, hands over the requester's own one; no colleague's is borrowed for it.
On sentences of our own against the boathouse (the rounds' office and sentences were never
read): Bram and Femi each own a stopwatch, Kasia owns a radio, Bram has no radio."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.boathouse import boathouse
from helpers.reading import frame_reader

_frame = frame_reader(boathouse, "bram")

Row = tuple[str, str | None, str | None, str]


def _tasks(text: str) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text).tasks]


@pytest.mark.parametrize(
    "text",
    [
        "drop the stopwatch off with Kasia pls, she's timing at 11",
        "take the stopwatch over to Kasia will ya",
        "give the stopwatch to Kasia",
        "can you bring Kasia the stopwatch",
        "pop the stopwatch over to kasia",
    ],
)
def test_the_item_the_requester_owns_is_their_own(text: str) -> None:
    assert _tasks(text) == [("transfer", "stopwatch", "bram", "kasia")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the requester has no radio: whose is still found by the planner
        ("take the radio over to Femi", [("transfer", "radio", None, "femi")]),
        # "a stopwatch": any one will do, left to the planner as before
        ("bring Kasia a stopwatch", [("transfer", "stopwatch", None, "kasia")]),
        # to the requester: one they do not have at hand, borrowed as before
        ("bring me the stopwatch", [("transfer", "stopwatch", None, "bram")]),
        # a named owner or source stays theirs
        ("take Femi's stopwatch to Kasia", [("transfer", "stopwatch", "femi", "kasia")]),
        ("take the stopwatch from Femi to Kasia", [("transfer", "stopwatch", "femi", "kasia")]),
        ("take my stopwatch to Kasia", [("transfer", "stopwatch", "bram", "kasia")]),
    ],
)
def test_other_ownership_is_unchanged(text: str, expected: list[Row]) -> None:
    assert _tasks(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "did you take the stopwatch to Kasia?",
        "thanks for taking the stopwatch to Kasia",
        "don't take the stopwatch to Kasia",
    ],
)
def test_a_question_thanks_or_negation_moves_nothing(text: str) -> None:
    assert _tasks(text) == []


async def test_the_requesters_own_stopwatch_goes_and_femi_is_not_asked() -> None:
    run = await run_instruction(boathouse(), "bram", "take the stopwatch over to Kasia will ya")
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    assert [r.action for r in trace.actions() if r.refused] == []
    contacts = {getattr(r.action, "contact", None) for r in trace.actions()}
    assert "femi" not in contacts
