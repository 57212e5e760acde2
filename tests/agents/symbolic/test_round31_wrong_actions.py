"""The wrong physical actions of blind rounds 32 and 33 (measured blind first; sentences of our
own on the default office): a taking the owner "won't notice" is declined; a quantity said as
the subject of a complaint ("half the staplers won't even staple") is told, not a fetch, also
after "to be frank"; "for a min" is a minute, nobody's name; "actually no, don't bother"
withdraws the request before it."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "take Zhang's lunch out of the fridge and give it to me, he won't notice",
        "go to Zhang's desk and take his stapler while he's out, he'll never notice",
        "grab Wang's seal, she won't even notice it's gone",
        # not missing it: the owner is not to notice either (blind round 70)
        "take Zhang's lunch out of the fridge and bring it to me, he won't miss it",
        "bring me Wang's stapler, she'll never miss it",
    ],
)
def test_a_taking_the_owner_is_not_to_notice_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "without the owner knowing" in frame.decline


def test_an_owner_who_will_not_mind_is_still_asked() -> None:
    frame = _frame("borrow Zhang's stapler, he won't mind")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "zhang", "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "to be frank, half the staplers won't even staple",
        "half the staplers won't staple",
        "most of the scissors are blunt, just so you know",
    ],
)
def test_a_complaint_about_some_of_a_thing_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame


def test_for_a_min_is_a_minute() -> None:
    frame = frame_reader(load_office, "hu")("borrow Wang's stapler for a min? mine's jammed")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "wang", "hu")]
    frame = frame_reader(load_office, "hu")("give my stapler to Min")
    assert [t.recipient for t in frame.tasks] == ["gao"]


@pytest.mark.parametrize(
    "text",
    [
        "print my report for me. actually no don't bother, I'll read it on screen",
        "print my report for me. no don't bother",
    ],
)
def test_a_stressed_dont_bother_withdraws(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None and "dropped" in frame.decline


def test_who_follows_the_mark_does_not_tell_the_owner() -> None:
    """ "she'll never notice we took it": the owner is kept in the dark whoever follows; only
    "without asking me" is the speaker's own say."""
    frame = _frame("take Wang's seal while she's out, she'll never notice we used it")
    assert frame.tasks == [] and frame.decline is not None, frame
    frame = _frame("print my file without asking me again")
    assert [t.kind for t in frame.tasks] == ["print"], frame
