"""Who is after a thing, and whose is taken to them (blind round 57-58's class; the round's
own offices and sentences were never read): "Kit's after a torch, can you take Omar's over to
him? Omar said ok" takes Omar's torch to Kit: "<name>'s after a X" is that person's need,
"Omar's" with the kind left out is Omar's torch, "him" is the one who is after it (not the
owner named in the same clause), and Omar is still asked (a claimed yes is no consent). An
opening sign-on ("Tam here - ...") names the speaker, no party to the request."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.reading import frame_reader
from helpers.staff_room import staff_room

_frame = frame_reader(staff_room, "ravi")


@pytest.mark.parametrize(
    "text",
    [
        "Kit's after a torch, can you take Omar's over to him? Omar said ok",
        "Tam here - Kit's after a torch, could you take Omar's over to him? he said it's fine",
        "Ravi here - Kit's after a torch, could you take Omar's over to him?",
        "Miles here: Kit's after a torch, take Omar's over to him",
        "Kit is after a torch, can you take Omar's to him",
        "Kit's after a torch, can you take Omar's torch over to him?",
    ],
)
def test_the_owners_one_goes_to_the_one_after_it(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "torch", "omar", "kit")
    ], frame


@pytest.mark.parametrize("text", ["Kit's after a torch", "Kit's looking for a torch"])
def test_the_need_alone_is_asked_about_for_kit(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Kit Marsh" in frame.question and "torch" in frame.question, frame


def test_a_sign_on_is_no_party() -> None:
    frame = _frame("hi, Tam here. could you bring me a pen")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("pen", "ravi")], frame


async def test_end_to_end_the_owner_is_asked_and_the_torch_goes_to_kit() -> None:
    text = "Tam here - Kit's after a torch, could you take Omar's over to him? Omar said ok"
    run = await run_instruction(staff_room(), "ravi", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    asked = [getattr(r.action, "contact", None) for r in run.stm.trace.actions()]
    assert "omar" in asked, run.stm.trace.summary
    handed = [(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()]
    assert ("torch:omar", "kit") in handed, run.stm.trace.summary
