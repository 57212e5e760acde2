"""Blind round 17's operation-wording classes, on a school arts block no sentence was written
for (``helpers.arts_block``; the round's office and sentences were never read): an operation
named by its facility ("go through the hot press", "guillotine my poster") with a detail
after it ("down to A4"), by a near form of the office's own verb ("flame-proofed" for
"fireproof", "dying" for "dye"), and "has to be <done>" as the need it is."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.task_schema import TaskFrame
from helpers.arts_block import arts_block
from helpers.reading import frame_reader

_frame = frame_reader(arts_block, "marta")


def _work(frame: TaskFrame) -> list[tuple[str | None, str | None, str | None, str]]:
    assert frame.question is None and frame.decline is None, frame
    return [(t.operation, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("who", "text", "op", "item"),
    [
        ("hatty", "can my tunic go through the hot press before assembly", "press", "tunic"),
        ("hatty", "Could you guillotine my poster down to A4 for me?", "crop", "poster"),
        ("hatty", "Could you crop my poster down to A5 please", "crop", "poster"),
        ("ewan", "could you run my poster through the guillotine", "crop", "poster"),
        ("marta", "can you fire-proof my banner", "fireproof", "banner"),
        ("marta", "my backdrop needs flame-proofing", "fireproof", "banner"),
        ("marta", "My banner has to be flame-proofed.", "fireproof", "banner"),
        (
            "marta",
            "The new banner has to be flameproofed before it goes on stage. Can you sort it?",
            "fireproof",
            "banner",
        ),
        ("marta", "My banner must be fireproofed before it goes on stage.", "fireproof", "banner"),
        ("hatty", "My tunic needs dying a darker red", "dye", "tunic"),
        ("priya", "could you get my costume dyed dark blue", "dye", "tunic"),
    ],
)
def test_the_operation_is_read_from_its_facility_or_a_near_form(
    who: str, text: str, op: str, item: str
) -> None:
    assert _work(_frame(text, who)) == [(op, item, who, who)]


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("My banner has been flameproofed already.", "Noted"),
        ("thanks for flameproofing my banner", "welcome"),
        ("my plant is dying", "Noted"),
    ],
)
def test_a_fact_or_thanks_with_a_near_form_still_moves_nothing(text: str, said: str) -> None:
    frame = _frame(text, "marta")
    assert frame.tasks == [] and frame.decline is not None and said in frame.decline


@pytest.mark.parametrize("text", ["did you flame-proof my banner?", "don't flameproof my banner"])
def test_a_question_or_negation_with_a_near_form_does_nothing(text: str) -> None:
    assert _frame(text, "marta").tasks == []


def test_a_capitalised_name_after_to_is_still_asked_about() -> None:
    asked = _frame("could you crop my poster and give it to Kowalski", "hatty").question
    assert asked is not None and "Kowalski" in asked


async def test_the_tunic_is_dyed_and_comes_back() -> None:
    run = await run_instruction(arts_block(), "hatty", "My tunic needs dying a darker red")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    asked = [m.text for m in run.sim.messenger.sent if m.chat.id == "bram"]
    assert any("dye" in a for a in asked), asked
    assert run.sim.world.holder["tunic:hatty"] == "hatty"


async def test_the_banner_is_fireproofed_and_comes_back() -> None:
    run = await run_instruction(
        arts_block(),
        "marta",
        "The new banner has to be flameproofed before it goes on stage. Can you sort it?",
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.holder["banner:marta"] == "marta"
