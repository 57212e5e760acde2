"""Tolerant reading of replies: real colleagues do not write like the simulator."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.answers import stance


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Yes, I have a stapler. Happy to lend it.", "yes"),
        ("yep, got one", "yes"),
        ("Sure, here is my file.", "yes"),
        ("No problem!", "yes"),
        ("of course, come by", "yes"),
        ("I can help with that (seal).", "yes"),
        ("No, I don't have a stapler.", "no"),
        ("nope", "no"),
        ("Sorry, I can't help with that (print).", "no"),
        ("yes but I'm busy all afternoon", "no"),
        ("I came to the robot, but: I don't have stapler:zhang.", "no"),
        ("unfortunately not today", "no"),
        ("what do you mean?", "unclear"),
        ("", "unclear"),
    ],
)
def test_stance(text: str, expected: str) -> None:
    assert stance(text) == expected
