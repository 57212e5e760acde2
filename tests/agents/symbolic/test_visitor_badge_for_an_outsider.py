"""A thing the office makes for people from outside, asked for an outside person by a
colleague ("need a visitor badge issued for a delivery driver", blind round 59's class,
analogue): it was declined as a credential for an outsider. The credential rule is about
handing what opens doors to outsiders, not about what a colleague may ask for themselves: the
badge is made and handed to the colleague who asked, who passes it on, and the reply says it
came to them. Someone's own credential for an outsider ("give Sam's door key to a delivery
driver") is still declined, and a badge to be handed on past the colleague ("..., bring it to
him at the gate") is answered in words: it can only come to them (asked, nothing moves)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.events_desk import events_desk
from helpers.reading import frame_reader

_frame = frame_reader(events_desk, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "need a visitor badge issued for a delivery driver",
        "can you issue a visitor badge for the courier?",
        "please issue a visitor badge for the contractor at reception",
        "could I get a visitor badge for our guest this afternoon",
        "issue a visitor badge for the plumber pls",
    ],
)
def test_a_visitor_badge_for_an_outsider_comes_to_the_colleague_who_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "visitor_badge", "ines")
    ], frame


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("give Sam's door key to a delivery driver", "a delivery driver"),
        ("take Sam's door key to the man at reception", "the man at reception"),
    ],
)
def test_someones_own_credential_for_an_outsider_is_still_declined(text: str, who: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.decline is not None and who in frame.decline, frame
    assert "keys, cards and passes" in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "issue me a visitor badge for the driver, bring it to him at the gate",
        "issue a visitor badge for the courier and take it to him",
    ],
)
def test_a_badge_handed_on_past_the_colleague_is_said_to_come_only_to_them(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.question is not None, frame
    assert "Shall I bring it to you instead, so you can pass it on?" in frame.question


async def test_end_to_end_the_badge_is_handed_to_the_requester_and_the_reply_says_so() -> None:
    run = await run_instruction(
        events_desk(), "ines", "need a visitor badge issued for a delivery driver"
    )
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    handed = [
        (e.detail["item"].partition(":")[0], e.detail["to"]) for e in run.sim.world.handovers()
    ]
    assert handed == [("visitor_badge", "ines")], trace.summary
    assert "handed to you" in (trace.summary or ""), trace.summary
