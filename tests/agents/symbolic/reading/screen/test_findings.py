"""What the screen made of a message: answered by the screen itself, or a request left."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import DROPPED, Screened


def test_a_decline_or_a_question_answers_the_message() -> None:
    assert Screened(text="", decline="You're welcome!").answered
    assert Screened(text="", question="Shall I bring you one?").answered
    assert not Screened(text="bring me a pen").answered


def test_what_declines_is_never_dropped_as_context() -> None:
    assert "destructive" not in DROPPED and "unsupported" not in DROPPED
    assert {"withdrawn", "negated", "fact", "statement"} <= DROPPED
