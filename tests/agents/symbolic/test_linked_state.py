"""A plural subject and a plain linking verb ("the copies look great", "the scans seem
fine") say how things are: after thanks it is a thank-you in words, alone a comment, never a
print or a question of what to do (reading/linked_state.py). A request beside it still moves
or asks; a command that opens with "look" is no statement."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office
from helpers.dataset_offices import default_office


@pytest.fixture(scope="module")
def default_parser() -> InstructionParser:
    return InstructionParser(default_office())


@pytest.mark.parametrize(
    ("text", "reply"),
    [
        ("thanks, the copies look great", "welcome"),  # asked what to do before
        ("thanks, the printouts look great", "welcome"),  # printed a file before
        ("thanks, the copies seem fine", "welcome"),
        ("ta, the labels look really neat", "welcome"),
        ("cheers, the coffee was perfect", "welcome"),
        ("ta, the printout's fine", "welcome"),
        ("the copies look great", "Noted"),
    ],
)
def test_a_comment_on_things_is_words(
    default_parser: InstructionParser, text: str, reply: str
) -> None:
    frame = default_parser.parse(text, "lee")
    assert not frame.tasks and frame.question is None, (text, frame)
    assert reply in (frame.decline or ""), (text, frame.decline)


@pytest.mark.parametrize("text", ["thanks, the copies look great", "cheers, the scans look fine"])
def test_a_comment_on_things_is_words_in_harbour(harbour: Office, text: str) -> None:
    frame = InstructionParser(harbour).parse(text, "may")
    assert not frame.tasks and frame.question is None, (text, frame)
    assert "welcome" in (frame.decline or ""), (text, frame.decline)


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("thanks, the pens look great, can you bring me a stapler?", "stapler", None),
        ("the staplers look broken, bring me Wang's stapler", "stapler", "wang"),
    ],
)
def test_a_request_beside_the_comment_still_moves(
    default_parser: InstructionParser, text: str, item: str, owner: str | None
) -> None:
    tasks = default_parser.parse(text, "lee").tasks
    assert [(t.item, t.owner) for t in tasks] == [(item, owner)], text


@pytest.mark.parametrize(
    "text",
    [
        "thanks, the copies look great, can I have two more?",  # more is asked: no thank-you
        "look at the copies",  # a command opens with its verb: no subject, no comment
    ],
)
def test_an_ask_is_not_taken_for_thanks(default_parser: InstructionParser, text: str) -> None:
    frame = default_parser.parse(text, "lee")
    assert frame.tasks or frame.question is not None, (text, frame)
