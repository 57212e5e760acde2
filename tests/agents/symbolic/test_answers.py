"""Tolerant reading of replies: real colleagues do not write like the simulator."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.answers import says_not_known, stance


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
        # a name with a diacritic is one word: "Noémie" holds no "no" (blind round 24: an
        # owner's yes naming the keeper was read as a no and the consent guard refused it)
        ("Yes, it's in the key safe: Noémie can take it out for the robot.", "yes"),
        ("Sure, ask Nöel", "yes"),
        ("No, Noémie has it", "no"),
        # a refusing word inside a name ("the negative vault", "the lost property box") is
        # no refusal: an owner's yes naming where the thing is kept was read as a no
        (
            "Yes, you can have my negatives. It is kept in the negative vault, not with me: "
            "Tom can take it out for the robot.",
            "yes",
        ),
        ("sure, it's in the lost property box", "yes"),
        ("yes, after the busy season", "yes"),
        ("yes but I lost it", "no"),
        ("sorry, it's in the negative vault", "no"),
        ("that's a negative", "no"),
        ("yes, I'm away", "no"),
    ],
)
def test_stance(text: str, expected: str) -> None:
    assert stance(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Sorry, I don't know.", True),
        ("Sorry, I don't know more than I wrote.", True),
        ("no idea", True),
        ("I'm not sure", True),
        ("To the regional federation.", False),
        ("Zhang Wei's.", False),
        ("I know: the county office", False),
        ("Don Knowles", False),
    ],
)
def test_a_reply_that_only_says_they_do_not_know(text: str, expected: bool) -> None:
    assert says_not_known(text) is expected
