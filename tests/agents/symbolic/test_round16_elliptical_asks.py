"""An elliptical ask with the speaker's reason is a request (blind round 16's class 3; the
round's office and sentences were never read). "got an exposure meter anywhere? want to check
the light before the run" asks for a light meter (by a declared synonym) for the speaker; "the
run" is a print run, not the courier that lists "run"; things the reason names ("the
negatives") are what the speaker already works on, never an errand of their own. A question
about the one thing ("got the light meter back from Will yet?", "who's got the light
meter?") and a bare "got a light meter?" stay questions, answered in words."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.gazette import newsroom
from helpers.reading import answered_reader

_frame = answered_reader(newsroom, "ines")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("got an exposure meter anywhere? want to check the light before the run", "light_meter"),
        ("got a light meter? want to check the light before the print", "light_meter"),
        ("anyone got a light meter? need to check the flash", "light_meter"),
        ("have you got a light meter? need to check the flash", "light_meter"),
        ("does anyone have an eyeglass? want to look at the negatives", "magnifying_glass"),
        (
            "got an eyeglass anywhere? want to look at the negatives before the print",
            "magnifying_glass",
        ),
        ("light meter anywhere? want to look at the negatives before the run", "light_meter"),
        ("got a magnifying glass handy? need it for the proofs", "magnifying_glass"),
        ("has anyone got a light meter I can borrow", "light_meter"),
    ],
)
def test_an_elliptical_ask_with_a_reason_is_a_request(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, "ines")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "got the light meter back from Will yet?",
        "who's got the light meter?",
        "got a light meter?",
        "got a light meter anywhere?",
        "got a minute?",
    ],
)
def test_questions_move_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []


def test_a_reason_that_asks_for_work_of_its_own_is_still_that_request() -> None:
    frame = _frame("got a light meter? want to print my draft")
    assert [(t.kind, t.item) for t in frame.tasks] == [("print", "file")]


async def test_a_run_brings_a_light_meter_and_nothing_else() -> None:
    run = await run_instruction(
        newsroom(), "ines", "got an exposure meter anywhere? want to check the light before the run"
    )
    assert run.stm.trace.outcome == "done"
    assert not run.sim.world.sent_out()
    moved = {e.detail["item"].partition(":")[0] for e in run.sim.world.handovers()}
    assert moved == {"light_meter"}
