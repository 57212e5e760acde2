"""Blind rounds 20-22's class (analogues, not the measured sentences): two-part errands with a
signature. The second clause opens on a word the lexicon has no cue for, a verb of asking
("... and ask Dov to sign my call sheet") or an everyday verb of handing ("..., and then pop a
rush tag over to me"), and ran on into the first clause (its part dropped or unexplained); a
pronoun doer ("get her to sign") is the one colleague named before, asked about when there is
none or several; and a personal paper "from" a company nobody in the office is ("the call
sheet from Harlow Dairy") is where the paper came from, nobody to look up."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.core.goals import Milestone
from assistantx.evaluation import metrics
from helpers.one_episode import ppdr_episode
from helpers.outside_broadcast import outside_broadcast

Read = tuple[str, str, str, str | None]  # kind, item, recipient, actor


def _tasks(instruction: str) -> list[Read]:
    reading = InstructionParser(outside_broadcast()).parse(instruction, "quill")
    return [(t.kind, t.item or "", t.recipient or "", t.actor) for t in reading.tasks]


def _question(instruction: str) -> str | None:
    return InstructionParser(outside_broadcast()).parse(instruction, "quill").question


SIGNED_BY_DOV = ("sign", "call_sheet", "quill", "dov")


@pytest.mark.parametrize(
    ("instruction", "tasks"),
    [
        (
            "send my tape to Piet and ask Dov to sign my call sheet",
            [("transfer", "tape", "piet", None), SIGNED_BY_DOV],
        ),
        (
            "send my tape to Dov and ask him to sign my call sheet",
            [("transfer", "tape", "dov", None), SIGNED_BY_DOV],
        ),
        (
            "fwd my rundown to Dawn and get her to sign my log sheet too pls",
            [("send_file", "rundown", "dawn", None), ("sign", "log_sheet", "quill", "dawn")],
        ),
        (
            "send my rundown to Dov and tell him to sign my call sheet",
            [("send_file", "rundown", "dov", None), SIGNED_BY_DOV],
        ),
        (
            "send my tape to Dov and get Sandy to sign my call sheet",
            [("transfer", "tape", "dov", None), ("sign", "call_sheet", "quill", "sandy")],
        ),
        (
            "please get Sandy to sign my call sheet, and then pop a rush tag over to me as well",
            [("sign", "call_sheet", "quill", "sandy"), ("produce", "rush_tag", "quill", None)],
        ),
        (
            "get Dawn to sign my call sheet and bung the headset round to Dov",
            [("sign", "call_sheet", "quill", "dawn"), ("transfer", "camera_headset", "dov", None)],
        ),
        (
            "please get Dov to sign the call sheet from Harlow Dairy",
            [SIGNED_BY_DOV],
        ),
        ("could Dov sign my call sheet from Arqiva please", [SIGNED_BY_DOV]),
        # the form brought is the one signed: one errand, as before
        ("bring Dov my call sheet and ask him to sign it", [SIGNED_BY_DOV]),
    ],
)
def test_both_parts_are_read(instruction: str, tasks: list[Read]) -> None:
    assert _tasks(instruction) == tasks


@pytest.mark.parametrize(
    ("instruction", "question"),
    [
        # nobody, or two people, "her" could be
        ("get her to sign my log sheet", "Who do you mean by 'her'? Please tell me their name."),
        (
            "send my tape to Dov and Piet and get him to sign my call sheet",
            "Who do you mean by 'him'? Please tell me their name.",
        ),
        # a thing from a name nobody has is still asked about when it is no paper
        (
            "bring me the headset from Harlow",
            "I don't know anyone called 'Harlow' in this office. Who do you mean?",
        ),
        ("get the call sheet from Harlow Dairy", "Whose call sheet do you mean?"),
    ],
)
def test_what_is_not_clear_is_asked(instruction: str, question: str) -> None:
    assert _tasks(instruction) == []
    assert _question(instruction) == question


@pytest.mark.parametrize(
    "instruction",
    [
        "did you ask Dov to sign my call sheet?",
        "thanks for sending my tape to Dov and asking him to sign my call sheet",
        "don't ask Dov to sign my call sheet",
    ],
)
def test_a_question_thanks_or_negation_moves_nothing(instruction: str) -> None:
    assert _tasks(instruction) == []


@pytest.mark.parametrize(
    ("instruction", "goal"),
    [
        (
            "send my rundown to Dov and ask him to sign my call sheet",
            [{"received": ["dov", "rundown:quill"]}, {"signed": ["call_sheet:quill", "dov"]}],
        ),
        (
            "please get Sandy to sign my call sheet, and then pop a rush tag over to me as well",
            [{"signed": ["call_sheet:quill", "sandy"]}, {"holds": ["quill", "rush_tag:quill"]}],
        ),
        (
            "please get Dov to sign the call sheet from Harlow Dairy",
            [{"signed": ["call_sheet:quill", "dov"]}],
        ),
    ],
)
async def test_the_errand_is_done_whole(instruction: str, goal: list[Milestone]) -> None:
    office = outside_broadcast()
    episode = await ppdr_episode(office, "quill", instruction, [*goal, {"informed": "quill"}])
    assert metrics.success(episode), (episode.milestones, episode.trace.summary)
    assert metrics.wrong_handovers(episode) == []
