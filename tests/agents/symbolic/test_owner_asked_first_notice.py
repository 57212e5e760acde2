"""The requester is told first that an owner will be asked (blind round 14's class 4; the
round's office and sentences were never read): "can I borrow Ottilie's step stool?" sends the
requester "I'll ask Ottilie Brandt first whether you may borrow their step stool ..." before
Ottilie is asked and before the robot moves; only once, in names, never ids. Requests that
need nobody's yes of their own item (the requester's own, a guard's work, a made thing) tell
nothing of the kind."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Action, Inform, Inquire, Move
from helpers.guesthouse import guesthouse


def _told_requester(actions: list[Action], requester: str) -> list[str]:
    return [a.content for a in actions if isinstance(a, Inform) and a.contact == requester]


@pytest.mark.parametrize(
    ("requester", "text", "owner", "may"),
    [
        ("wren", "can I borrow Ottilie's step stool?", "Ottilie Brandt", "you may borrow"),
        ("wren", "Please get me Basil's hole punch for a bit.", "Basil Moreau", "you may borrow"),
        ("cosmo", "bring me Juniper's hole punch", "Juniper Hale", "you may borrow"),
        (
            "wren",
            "could you bring Basil Ottilie's step stool",
            "Ottilie Brandt",
            "Basil Moreau may borrow",
        ),
    ],
)
async def test_the_requester_hears_the_owner_will_be_asked_before_anything_else(
    requester: str, text: str, owner: str, may: str
) -> None:
    run = await run_instruction(guesthouse(), requester, text)
    acted = [r.action for r in run.stm.trace.actions() if not r.refused]
    told = _told_requester(acted, requester)
    assert len(told) == 1
    assert told[0].startswith(f"I'll ask {owner} first whether {may} their ")
    assert ":" not in told[0] and "_" not in told[0]  # no internal ids
    first_inform = next(k for k, a in enumerate(acted) if isinstance(a, Inform))
    first_ask = next(k for k, a in enumerate(acted) if isinstance(a, Inquire))
    moves = [k for k, a in enumerate(acted) if isinstance(a, Move)]
    assert first_inform < first_ask
    assert not moves or first_inform < moves[0]


@pytest.mark.parametrize(
    ("requester", "text"),
    [
        ("wren", "laminate my poster"),
        ("wren", "brew me a tea"),
        ("basil", "shred my ledger"),
        ("wren", "take my step stool to Basil"),
    ],
)
async def test_no_owner_to_ask_tells_nothing_of_the_kind(requester: str, text: str) -> None:
    run = await run_instruction(guesthouse(), requester, text)
    acted = [r.action for r in run.stm.trace.actions() if not r.refused]
    assert not [t for t in _told_requester(acted, requester) if t.startswith("I'll ask")]
