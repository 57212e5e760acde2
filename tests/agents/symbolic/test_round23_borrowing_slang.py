"""Blind rounds 23 and 24, class 2: asking to borrow anyone's thing in slang ("anyone got a
stopwatch I can nab?", "... going spare?"). The ask itself says the thing is for the speaker
(one "spare", or "I can/could" and a verb after the thing), so it is a request for anyone's,
its owners asked; a bare "anyone got a (spare) stopwatch?" is still answered and offered, a need for
later still waits. On sentences of our own against a training ground no sentence was written
for (the rounds' office and sentences were never read)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.compound_heads import modifies_a_noun
from assistantx.agents.symbolic.reading.tokens import tokenize
from helpers.reading import frame_reader
from helpers.training_ground import training_ground

_frame = frame_reader(training_ground, "owen")

_ANYONES = [("transfer", "stopwatch", None, "owen")]


def _tasks(text: str) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text).tasks]


@pytest.mark.parametrize(
    "text",
    [
        "anyone got a stopwatch i can nab?",
        "anyone got a stopwatch going spare? mine's off being calibrated till thurs",
        "does anyone have a stopwatch i can nab?",
        "has anyone got a stopwatch spare?",
        "anyone got a stopwatch we could pinch for the session",
        "anyone got a stopwatch i can borrow?",
    ],
)
def test_an_ask_that_says_it_is_for_me_borrows_anyones(text: str) -> None:
    assert _tasks(text) == _ANYONES


@pytest.mark.parametrize(
    "text",
    [
        "anyone got a stopwatch?",  # answered, then offered
        "has anyone got a spare stopwatch?",  # which kind, no borrowing: answered
        "who has a stopwatch i can nab?",  # a wh-question: answered
        "does anyone have a stopwatch i could use tomorrow?",  # later: nothing now
        "anyone got a stopwatch i can nab? no worries, found mine",  # withdrawn
    ],
)
def test_a_bare_question_a_later_need_or_a_withdrawal_moves_nothing(text: str) -> None:
    assert _tasks(text) == []


@pytest.mark.parametrize(
    ("text", "compound"),
    [
        ("a stopwatch i can nab", False),  # "i": a pronoun, though listed as a noun
        ("a stopwatch going spare", False),  # what it is doing
        ("a stopwatch sitting idle", False),
        ("a stopwatch going", False),
        ("a stopwatch training plan", True),  # an -ing noun before a noun: a compound
        ("a stopwatch list", True),
    ],
)
def test_a_pronoun_or_what_the_item_is_doing_is_no_compound_head(text: str, compound: bool) -> None:
    tokens = tokenize(text)
    assert modifies_a_noun(tokens, 2, lambda word: word == "stopwatch") is compound


async def test_the_owners_are_asked_before_a_stopwatch_moves() -> None:
    run = await run_instruction(training_ground(), "owen", "anyone got a stopwatch i can nab?")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    # main asked "what do you need?" and moved nothing
    assert run.actions[0] == "inquire", run.actions  # an owner asked before anything moved
    assert "send_qr" in run.actions, run.actions
