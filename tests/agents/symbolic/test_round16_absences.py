"""A statement of someone's absence gets words, never an errand (blind round 16's class 6;
the round's office and sentences were never read). "fyi Ramón's out on a delivery till 3" is
read like "Ramón's out till 3": noted as away, nothing done; a request beside it is still
done, and the absence is a hint for its plan."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Inquire, Move
from helpers.gazette import newsroom
from helpers.reading import answered_reader

_frame = answered_reader(newsroom, "ines")


@pytest.mark.parametrize(
    ("text", "person"),
    [
        ("fyi Ramón's out on a delivery till 3", "ramon"),
        ("Ramón's out on a delivery till 3", "ramon"),
        ("fyi Åsa's out on a shoot till 3", "asa"),
        ("Zoë's out on a job until noon", "zoe"),
        ("heads up, Will is out at the printers till 2", "will"),
        ("Bjørn is off on a course today btw", "bjorn"),
        ("heads up, Zoë is off sick today", "zoe"),
        ("Will's in a meeting until 4 btw", "will"),
    ],
)
def test_an_absence_is_noted_in_words(text: str, person: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and "noted" in frame.decline
    assert frame.away() == {person}


@pytest.mark.parametrize(
    ("text", "task", "away"),
    [
        (
            "Ramón's out on a delivery till 3, can you bring me Will's light meter",
            ("transfer", "light_meter", "will"),
            "ramon",
        ),
        (
            "Åsa's off on a shoot today. bring me a long lens",
            ("transfer", "long_lens", None),
            "asa",
        ),
    ],
)
def test_a_request_beside_it_is_still_done(
    text: str, task: tuple[str, str, str | None], away: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [task]
    assert away in frame.away()


async def test_an_absence_moves_nothing_and_asks_nobody() -> None:
    run = await run_instruction(newsroom(), "ines", "fyi Ramón's out on a delivery till 3")
    acted = [r.action for r in run.stm.trace.actions()]
    assert not [a for a in acted if isinstance(a, Inquire | Move)]
    assert not run.sim.world.handovers()
