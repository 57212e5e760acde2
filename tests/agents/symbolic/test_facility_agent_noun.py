"""A facility named by the agent noun of its operation's verb ("the charger" of a charging rack
that charges radios, also the head word of its synonym "radio charger"): "put/chuck/stick/pop/
throw X on/in the charger" asks for that operation on X, brought back to the speaker (blind
round 59's class: "Who should get your radio?"). A flat or dead thing said before it is the
reason. The agent noun in a statement is a report in words, and a throw into a bin or away is
still declined."""

from __future__ import annotations

import pytest

from helpers.edit_suite import edit_suite
from helpers.reading import frame_reader

_frame = frame_reader(edit_suite, "nadia")


@pytest.mark.parametrize(
    "text",
    [
        "my radio's flat, chuck it on the charger would you",
        "pop my radio in the charger",
        "stick my handset on the charger pls",
        "my radio is dead, throw it on the charger",
        "toss my radio onto the charging rack pls",
        "put my radio on the radio charger",
        "can you put my radio on the chargers",
    ],
)
def test_put_on_the_agent_noun_runs_its_operation(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("radio", "nadia", "nadia", "charge")
    ], frame


@pytest.mark.parametrize("text", ["the charger is broken", "the charger's not working"])
def test_the_agent_noun_in_a_statement_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "charging rack" in frame.decline


@pytest.mark.parametrize("text", ["throw my radio away", "throw Oskar's radio in the bin"])
def test_a_throw_that_disposes_is_still_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None and "won't" in frame.decline, frame
