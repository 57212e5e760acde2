"""Blind rounds 20-22's class (an analogue, not the measured sentence): a self-introduction
and a chain of corrections ("its dov, could u tag... sorry, COURIER, nope, i mean get Chloë's
curling tongs for me"). A correction corrected again at once says nothing that stands: the
last one of the chain is what the first corrects to, so the request said last is done and
the withdrawn work never runs. A chain of names ends on its last name; a chain that ends on
no request moves nothing."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.evaluation import metrics
from helpers.one_episode import ppdr_episode
from helpers.outside_broadcast import outside_broadcast

Read = tuple[str, str, str | None, str]  # kind, item, owner, recipient
CHLOES_TONGS: Read = ("transfer", "curling_tongs", "chloe", "dov")


def _tasks(instruction: str) -> list[Read]:
    reading = InstructionParser(outside_broadcast()).parse(instruction, "dov")
    return [(t.kind, t.item or "", t.owner, t.recipient or "") for t in reading.tasks]


@pytest.mark.parametrize(
    ("instruction", "tasks"),
    [
        (
            "its dov, could u tag... sorry, COURIER, nope, i mean get Chloë's curling tongs for me",
            [CHLOES_TONGS],
        ),
        (
            "could you courier... sorry, TAG, nah, I mean bring me chloe's curling tongs",
            [CHLOES_TONGS],
        ),
        (
            "dov here - could u tag - sorry, print, no wait, i meant fetch Chloë's curling "
            "tongs for me",
            [CHLOES_TONGS],
        ),
        # a chain of owners ends on the last one
        (
            "bring me Renée's headset, sorry, Anouk's, no wait, Quill's",
            [("transfer", "camera_headset", "quill", "dov")],
        ),
        # one correction, as before
        (
            "could u tag... sorry, i mean get Chloë's curling tongs for me",
            [CHLOES_TONGS],
        ),
    ],
)
def test_the_request_said_last_is_done(instruction: str, tasks: list[Read]) -> None:
    assert _tasks(instruction) == tasks


@pytest.mark.parametrize(
    "instruction",
    [
        "could u tag... sorry, COURIER, nope, i mean thanks anyway",
        "could u courier... sorry, TAG, nope, never mind",
        "did u get Chloë's curling tongs... sorry, I mean Renée's?",
    ],
)
def test_a_chain_that_ends_on_no_request_moves_nothing(instruction: str) -> None:
    assert _tasks(instruction) == []


async def test_the_corrected_errand_is_done_and_the_owner_asked() -> None:
    office = outside_broadcast()
    instruction = (
        "its dov, could u tag... sorry, COURIER, nope, i mean get Chloë's curling tongs for me"
    )
    episode = await ppdr_episode(
        office, "dov", instruction, [{"holds": ["dov", "curling_tongs:chloe"]}, {"informed": "dov"}]
    )
    assert metrics.success(episode), (episode.milestones, episode.trace.summary)
    asked = [
        getattr(r.action, "contact", None)
        for r in episode.trace.actions()
        if r.action.type == "inquire"
    ]
    assert "chloe" in asked
