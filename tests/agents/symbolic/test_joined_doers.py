"""Colleagues joined by "and" (or "then") as the doers of a person's work each do it: "get my
contract signed by Wang and Zhang" is one signature by each, in the order said, the paper
back to its owner between them (``reading.joined_doers``). Read one name at a time, the
second signer was dropped and the requester told it was done."""

from __future__ import annotations

import pytest

from assistantx.core.goals import Milestone
from assistantx.evaluation import metrics
from helpers.dataset_offices import default_office, harbour_office
from helpers.one_episode import ppdr_episode
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lin")
_HARBOUR = frame_reader(harbour_office, "will")

Read = tuple[str, str | None, str | None, str, str | None]  # kind, item, owner, recipient, actor


def _tasks(frame: object) -> list[Read]:
    return [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in getattr(frame, "tasks", [])]


def _signed_by(office: str, *signers: str) -> list[Read]:
    return [("sign", "document", office, office, who) for who in signers]


@pytest.mark.parametrize(
    ("text", "signers"),
    [
        ("I need my contract signed by Wang and Zhang", ("wang", "zhang")),
        ("I need Wang and Zhang to sign my contract", ("wang", "zhang")),
        ("ask Wang, Zhang and Mao to sign my document", ("wang", "zhang", "mao")),
        ("get my contract signed by Wang, then by Zhang", ("wang", "zhang")),
        ("get my document signed by Zhang and then Wang pls", ("zhang", "wang")),
        ("could Sun and Hu sign my contract?", ("sun", "hu")),
        # a quantifier floated after the subject: "both", "each"
        ("could Sun and Hu both sign my contract?", ("sun", "hu")),
        ("can Wang and Zhang each sign my document", ("wang", "zhang")),
    ],
)
def test_default_each_signs(text: str, signers: tuple[str, ...]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == _signed_by("lin", *signers), frame


@pytest.mark.parametrize(
    ("text", "signers"),
    [
        ("get my document signed by Rose and Mark", ("rose", "mark")),
        ("can Hope, Faith and Dawn sign my document", ("hope", "faith", "dawn")),
    ],
)
def test_harbour_each_signs(text: str, signers: tuple[str, ...]) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == _signed_by("will", *signers), frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # one signer, and the signed paper handed on to another: no group of signers
        (
            "get Wang to sign my document, then bring it to Zhang",
            [("sign", "document", "lin", "zhang", "wang")],
        ),
        # a signature and a coffee for someone else: the coffee's recipient signs nothing
        (
            "get my contract signed by Wang and bring Zhang a coffee",
            [
                ("sign", "document", "lin", "lin", "wang"),
                ("produce", "coffee", None, "zhang", None),
            ],
        ),
    ],
)
def test_one_signer_stays_one(text: str, tasks: list[Read]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == tasks, frame


@pytest.mark.parametrize(
    "text",
    [
        "bring my stapler to Wang and Zhang",
        # "both" floated after the group of the need: the group still receives (it was the
        # requester who got Wang's stapler: a wrong hand-over)
        "Wang and Zhang both need a stapler",
    ],
)
def test_one_thing_for_two_people_is_still_asked(text: str) -> None:
    """A group that receives is no group of doers: one stapler, whose to get it is asked."""
    frame = _DEFAULT(text)
    assert frame.question is not None and "only one of them" in frame.question, frame


def test_both_need_a_made_thing_each() -> None:
    frame = _DEFAULT("Wang and Zhang both need a coffee")
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "coffee", "wang"),
        ("produce", "coffee", "zhang"),
    ], frame


async def test_both_signatures_are_collected() -> None:
    """Run end to end in the simulated office: both sign, and the paper comes back."""
    office = default_office()
    goal: list[Milestone] = [
        {"signed": ["document:lin", "wang"]},
        {"signed": ["document:lin", "zhang"]},
        {"holds": ["lin", "document:lin"]},
        {"informed": "lin"},
    ]
    episode = await ppdr_episode(office, "lin", "I need my contract signed by Wang and Zhang", goal)
    assert metrics.success(episode), (episode.milestones, episode.trace.summary)
    assert metrics.wrong_handovers(episode) == []
