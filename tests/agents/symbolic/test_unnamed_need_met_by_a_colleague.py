"""A person named by what they are needs a thing, then the thing is asked for a colleague
("an intern needs a stapler. could you bring one to Wang?"): the colleague is how it reaches
them, one hand-over (``reading.needs_met.unnamed_need_met``); the need read as the speaker's
own had made a second one for the speaker (a wrong physical action of blind round 191). Said
alone, the need is still restated and asked; a request for something else keeps both."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("An intern needs a stapler. Could you bring one to Wang?", "stapler"),
        ("a visitor needs a pen. could you take one to Wang", "pen"),
        (
            "One of the beginners needs a pen. Could you bring one to Wang? She's teaching.",
            "pen",
        ),
        ("a trainee needs scissors, can you take some to Zhang", "scissors"),
    ],
)
def test_one_thing_to_the_colleague_named(text: str, item: str) -> None:
    tasks = tasks_of("default", text, "lee")
    assert len(tasks) == 1 and tasks[0][0] == "transfer" and tasks[0][1] == item
    assert tasks[0][3] in ("wang", "zhang")


def test_the_need_alone_is_asked() -> None:
    frame = parser("default").parse("an intern needs a stapler", "lee")
    assert frame.tasks == [] and frame.question == "Shall I bring a stapler to you?"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "Wang needs a stapler. Could you bring one to her?",
            [("transfer", "stapler", None, "wang")],
        ),
        (
            "make me a coffee and bring Wang one too",
            [("produce", "coffee", None, "lee"), ("produce", "coffee", None, "wang")],
        ),
    ],
)
def test_neighbours_read_as_before(
    text: str, expected: list[tuple[str, str, str | None, str]]
) -> None:
    assert tasks_of("default", text, "lee") == expected
