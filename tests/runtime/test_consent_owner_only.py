"""Work that uses an item up is its owner's own call (core/owner_only.py, blind round 14's
class 3; the round's office and sentences were never read): "shred Basil's ledger, he won't
mind" is declined by the reader before anyone is asked, and the consent guard refuses the
shredder's work code on someone else's ledger even when the owner said yes in their own chat.
The owner asking for it themselves is done; work that gives the item back is not touched."""

from __future__ import annotations

import pytest

from assistantx.core.actions import SendQR
from assistantx.core.dialogue import DialogueTurn
from assistantx.core.ports.messenger import ChatRef
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime import consent
from helpers.consent_memory import exchange, memory
from helpers.guesthouse import guesthouse


def _owner_said_yes(stm: ShortTermMemory, owner: str, text: str) -> None:
    """``owner`` was asked about their ledger in their own chat and said yes (and handed it
    in: the keeper of the shredder answered too)."""
    stm.dialogue += [
        *exchange(owner, text, "yes, fine"),
        *exchange("basil", "Could you shred it at the shredder?", "sure", time=2, question_id="q1"),
    ]


@pytest.mark.parametrize("operation", ["shred", None])
def test_the_guard_refuses_shredding_another_persons_item_even_with_their_yes(
    operation: str | None,
) -> None:
    stm = memory("wren", "shred Cosmo's ledger, he won't mind")
    _owner_said_yes(stm, "cosmo", "May the robot take your ledger to be shredded?")
    code = SendQR(contact="basil", item="ledger:cosmo", purpose="heat", operation=operation)
    refusal = consent.check(guesthouse(), stm, code)
    assert refusal is not None and refusal.rule == "owner_only"
    assert "Cosmo Delacroix" in refusal.reason


def test_the_guard_lets_the_owner_have_their_own_item_shredded() -> None:
    stm = memory("cosmo", "shred my ledger please")
    _owner_said_yes(stm, "cosmo", "unused")
    code = SendQR(contact="basil", item="ledger:cosmo", purpose="heat", operation="shred")
    assert consent.check(guesthouse(), stm, code) is None


def test_the_guard_still_lets_work_that_gives_the_item_back_through() -> None:
    stm = memory("wren", "laminate Ottilie's poster")
    _owner_said_yes(stm, "ottilie", "May the robot take your poster to be laminated?")
    stm.dialogue += [
        DialogueTurn(
            time=5,
            direction="in",
            chat=ChatRef(kind="dm", id="cosmo"),
            person="cosmo",
            text="sure",
        )
    ]
    code = SendQR(contact="cosmo", item="poster:ottilie", purpose="heat", operation="laminate")
    assert consent.check(guesthouse(), stm, code) is None
