""" "Keiko needs a bone folder for her moss packets, can you take mine to her": the thing a
purpose names ("for her moss packets") is what the other thing is used on, never what an
elided possessive ("mine", "Mao's") means; it means the thing needed. The speaker's own
packet was handed over instead of the bone folder (round 230)."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "sun")


@pytest.mark.parametrize(
    ("text", "task"),
    [
        (
            "Wang needs scissors for his paper, can you take mine to him",
            ("scissors", "sun", "wang"),
        ),
        ("I need the stapler for my documents, can I have Mao's", ("stapler", "mao", "sun")),
        ("Wang needs a stapler for the paper, give him mine", ("stapler", "sun", "wang")),
    ],
)
def test_mine_means_the_thing_needed(text: str, task: tuple[str, str, str]) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        # no purpose: the thing named last before "mine" is still what it means
        ("my stapler's broken, can I have Mao's", ("stapler", "mao", "sun")),
    ],
)
def test_must_not_change(text: str, task: tuple[str, str, str]) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


def test_a_person_after_for_is_no_purpose() -> None:
    # "for Mao" says whom it is for: "mine" still means the scissors named before it
    frame = _frame("Wang needs scissors for Mao, can you take mine")
    assert any(e.words == "mine" and e.meaning == "my scissors" for e in frame.evidence), frame
