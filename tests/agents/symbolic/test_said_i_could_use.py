"""A pronoun after "<person> said I could use her ..." is that person (blind round 57-58's
class; the round's own offices and sentences were never read): "Dr N said I could use her
goggles, could you bring them up to me?" is Dr N's goggles, with Dr N still asked (a claimed
yes is no consent); the subject of the reporting clause is what "her"/"his" points back to,
also when it is a title and an initial."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.reading import frame_reader
from helpers.staff_room import staff_room

_frame = frame_reader(staff_room, "kit")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        (
            "Dr N said I could use her goggles from the prep cabinet, could you bring them up "
            "to me?",
            "goggles",
            "nadia",
        ),
        ("Dr N said I could use her goggles, could you bring them up to me?", "goggles", "nadia"),
        ("Nadia said I could borrow her goggles, can you bring them to me", "goggles", "nadia"),
        ("Mr K told me I could use his pen, bring it to me please", "pen", "kofi"),
    ],
)
def test_the_pronoun_is_the_one_who_said_so(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, owner, "kit")], frame


async def test_end_to_end_the_owner_is_still_asked() -> None:
    text = "Dr N said I could use her goggles, could you bring them up to me?"
    run = await run_instruction(staff_room(), "kit", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    asked = [getattr(r.action, "contact", None) for r in run.stm.trace.actions()]
    assert "nadia" in asked, run.stm.trace.summary
