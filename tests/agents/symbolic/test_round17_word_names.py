"""Ordinary words that are names, and what an unhelpful answer does (blind round 17's class,
on a school office no sentence was written for, ``helpers.playschool``: a colleague called
Miles, one called Penny, the prep room's technician known as "Luke"). "prep room is miles away
from S4" is a distance, no colleague; "could Luke make up a kit" asks the technician's kit.
A requester who can only say "Sorry, I don't know more than I wrote." to a question is told
the request was not understood, never "OK, I won't do anything" (that is for a no)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.offer_reply import plain_stance
from helpers.playschool import playschool
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(playschool, "ada")
_answered = answered_reader(playschool, "ada")
_NOTHING_TO_ADD = "Sorry, I don't know more than I wrote."


@pytest.mark.parametrize(
    "text",
    [
        "prep room is miles away from S4 and I've got no free, could Luke make up a kit for my "
        "practical?",
        "could Luke make up a practical kit for me",
        "prep room is Miles away from S4 and I've got no free, could Luke make up a kit for my "
        "practical?",
        "the prep room is Miles away, could Luke make up a kit for me",
        "the prep room is miles from here, can Luke make up a kit for me please",
        "I've got a practical in S4 and a penny for every time I've asked... could Luke make "
        "up a kit?",
    ],
)
def test_a_kit_is_made_for_the_requester(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "practical_kit", "ada")
    ]


@pytest.mark.parametrize(
    ("text", "owner", "recipient"),
    [
        ("Miles is away, bring his stapler to me", "miles", "ada"),
        ("Penny is Miles away from here, bring me Rory's stapler", "rory", "ada"),
    ],
)
def test_miles_as_a_subject_is_still_the_colleague(text: str, owner: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", owner, recipient)]


def test_is_miles_away_asks_rather_than_guesses() -> None:
    frame = _frame("is Miles away today? bring him Rory's stapler")
    assert frame.tasks == [] and frame.question is not None


def test_a_named_colleague_is_still_the_colleague() -> None:
    frame = _frame("could you bring Miles Rory's stapler")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "rory", "miles")]
    frame = _frame("take my stapler to Penny please")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("stapler", "penny")]


@pytest.mark.parametrize(
    "answer",
    [_NOTHING_TO_ADD, "Sorry, I don't know.", "not sure, sorry", "I don't know, I just need it"],
)
def test_an_unhelpful_answer_is_no_no(answer: str) -> None:
    assert plain_stance(answer) != "no"


@pytest.mark.parametrize(
    "text",
    [
        "can u bring it down to me when you get a sec",
        "prep room is Miles away from S4, could you bring it over?",
        "Miles needs Rory's stapler",
    ],
)
def test_an_unhelpful_answer_leaves_the_question_open(text: str) -> None:
    first = _frame(text)
    assert first.question is not None
    after = _answered(text, [_NOTHING_TO_ADD])
    assert after.tasks == [] and after.decline is None, after
    assert after.question is not None


@pytest.mark.parametrize("answer", ["No, thanks.", "never mind"])
def test_a_no_to_an_offer_does_nothing(answer: str) -> None:
    after = _answered("Miles needs Rory's stapler", [answer])
    assert after.tasks == []
    assert after.question is None or answer == "never mind"


async def test_the_requester_is_told_the_request_was_not_understood() -> None:
    run = await run_instruction(playschool(), "ada", "can u bring it down to me when you get a sec")
    trace = run.stm.trace
    assert trace.outcome == "failed"
    assert "could not understand" in (trace.summary or "")
    assert "won't do anything" not in (trace.summary or "")
    moved = [r.action for r in trace.actions() if r.action.type in ("move", "send_qr")]
    assert moved == []
