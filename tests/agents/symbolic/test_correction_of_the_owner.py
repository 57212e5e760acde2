"""A correction that switches the owner, "actually no, <person>'s", replaces the owner said
before it (blind rounds 57-58's class: "X's charger pls, mine's at home. actually no, Y's - X's
in the board room all morning" was not understood: "actually no" was read as a withdrawal of
the request, leaving "Y's" alone). "actually" before "no" / "sorry" / "no wait" opens a
correction like the words after it; the requester's own ("mine's at home") and the reason
after a dash or a comma (naming the old owner) are context. "actually no, don't bother" and
"actually no, forget it" still withdraw the request."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "wang")


@pytest.mark.parametrize(
    "text",
    [
        "Zhang's stapler pls, mine's at home. actually no, Chen's - Zhang's in the board room "
        "all morning",
        "bring me Zhang's stapler. actually no, Chen's - Zhang's in the meeting room",
        "bring me Zhang's stapler, mine's at home. actually no, Chen's",
        "could you get me Zhang's stapler? actually, no, Chen's, Zhang needs his today",
        "grab me Zhang's stapler. Actually sorry, Chen's",
    ],
)
def test_the_owner_is_switched(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "chen", "wang")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "print my report for me. actually no, don't bother",
        "bring me Zhang's stapler. actually no, forget it",
    ],
)
def test_a_withdrawal_is_still_a_withdrawal(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame


async def test_end_to_end_the_new_owner_is_asked_not_the_old() -> None:
    text = "Zhang's stapler pls, mine's at home. actually no, Chen's - Zhang's in the board room"
    run = await run_instruction(load_office(), "wang", text)
    trace = run.stm.trace
    contacts = {getattr(r.action, "contact", None) for r in trace.actions()}
    assert "chen" in contacts and "zhang" not in contacts, trace.summary
