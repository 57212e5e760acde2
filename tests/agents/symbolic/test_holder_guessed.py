"""A request followed by a guess at who has one ("can u grab me a ruler, Olu's got one i think",
"need scissors - pretty sure Dana has a pair") names where to look: that person's is borrowed,
their consent asked (blind round 55's class; its office and sentences were never read). The
"I" of the speaker's hedge ("i think", "I'm pretty sure") is no speaker who has one, so the
guess is never read as "what was asked for is had already". A withdrawal before it, or the
speaker's own having, still drops the request; the guess alone moves nothing."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.reading import frame_reader
from helpers.sample_lab import sample_lab

_frame = frame_reader(sample_lab, "rhea")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("hey can u grab me a ruler, Olu's got one i think", "ruler", "olu"),
        ("can you bring me a ruler, Dana's got one I reckon", "ruler", "dana"),
        ("bring me a ruler, I'm pretty sure Dana's got one", "ruler", "dana"),
        ("need scissors - pretty sure Dana has a pair", "scissors", "dana"),
        ("could someone get me a pair of scissors? Olu has some I believe", "scissors", "olu"),
        ("grab me a ruler pls, i think Olu has one", "ruler", "olu"),
    ],
)
def test_a_guessed_holder_is_where_to_borrow_it(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "rhea")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "never mind, Olu's got one",
        "can you grab me a ruler, oh actually I've got one already",
        "bring me a ruler - I already have one i think",
        "bring me a ruler - oh Olu just brought me one",
    ],
)
def test_a_withdrawal_or_the_speakers_own_still_drops_it(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "dropped" in frame.decline, frame


@pytest.mark.parametrize("text", ["Olu's got one already", "Olu's got one i think"])
def test_the_guess_alone_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame


async def test_end_to_end_the_guessed_holder_lends_it() -> None:
    run = await run_instruction(
        sample_lab(), "rhea", "hey can u grab me a ruler, Olu's got one i think"
    )
    trace = run.stm.trace
    contacts = {getattr(r.action, "contact", None) for r in trace.actions()}
    assert "olu" in contacts, trace.summary
    assert "Olu Bakare's ruler" in trace.summary, trace.summary
