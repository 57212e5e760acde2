"""A tool named by the purpose someone lacks it for ("Hal has nothing to write with. Could
someone lend him something?") is the office's item declared for that purpose, for them (blind
round 43-44's class F4: read as a statement, then "I'm not sure what you need"). The lack is
that person's need of something for the purpose; said alone it is asked about as any need."""

from __future__ import annotations

import pytest

from helpers.nursery_yard import nursery_yard
from helpers.reading import frame_reader

_frame = frame_reader(nursery_yard, "ada")


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("Hal has nothing to write with. Could someone lend him something?", "pen", "hal"),
        ("Min's got nothing to cut with, can you find her something", "scissors", "min"),
        ("Hal has got nothing to write with, bring him something pls", "pen", "hal"),
        ("Min has nothing to cut with, could you get her something", "scissors", "min"),
        ("I have nothing to write with. Could you bring me something?", "pen", "ada"),
        ("I've got nothing to cut with, can you find me something", "scissors", "ada"),
    ],
)
def test_a_tool_lacked_for_a_purpose_is_brought(text: str, item: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", item, recipient)
    ], frame


def test_the_lack_alone_is_asked_about() -> None:
    frame = _frame("Hal has nothing to write with.")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "pen" in frame.question and "Hal" in frame.question


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("Hal has a pen to write with.", []),
        ("Can you bring Hal a pen", [("transfer", "pen", "hal")]),
        ("Hal needs something to write with, can you bring him one", [("transfer", "pen", "hal")]),
    ],
)
def test_near_misses_keep_their_reading(text: str, tasks: list[tuple[str, str, str]]) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == tasks, frame
