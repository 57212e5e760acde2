"""Give-back errands survive a restart (SIGTERM or kill -9).

An instruction that ends with someone's item in the locker starts an errand that brings it
back (``runtime.returns``). The ended instruction is journaled as owing a give-back in the
same transaction as its ``instruction_ended`` (a crash cannot fall between the two), and
journaled as settled when its errand is over. On start-up every errand still owed starts
again from the instruction's journaled memory, for the items the simulated world still has in
the locker (one handed back before the crash is not fetched twice); each start counts as an
attempt: the owner is told again why the robot comes, with a fresh code.
"""

from __future__ import annotations

import logging
from typing import Any

from assistantx.core.office import Office
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.returns import items_to_return
from assistantx.store.journal import Journal

logger = logging.getLogger(__name__)

GIVE_BACK_STATE = "give_back"


class GiveBacks:
    """The ended instructions whose give-back errand is not over, with its attempts so far."""

    def __init__(self, journal: Journal, office: Office) -> None:
        self.journal = journal
        self.office = office
        body = journal.state(GIVE_BACK_STATE) or {}
        self.owed: dict[str, int] = {str(k): int(v) for k, v in body.get("owed", {}).items()}

    def state(self) -> dict[str, dict[str, Any]]:
        """The state row to journal (with the transaction that changes it)."""
        return {GIVE_BACK_STATE: {"owed": dict(self.owed)}}

    def on_end(self, stm: ShortTermMemory) -> dict[str, dict[str, Any]]:
        """For the ``instruction_ended`` transaction: the row owing ``stm``'s give-back, or
        nothing when it leaves nothing in the locker."""
        if not items_to_return(self.office, stm):
            return {}
        self.owed.setdefault(stm.instruction_id, 0)
        return self.state()

    def settle(self, instruction_id: str) -> dict[str, dict[str, Any]]:
        """The row without ``instruction_id``: its errand is over."""
        self.owed.pop(instruction_id, None)
        return self.state()

    def to_resume(self, in_locker: set[str]) -> list[tuple[ShortTermMemory, int]]:
        """The ended instructions' memories (their items narrowed to those still in the
        locker) and each one's attempt number; the ones with nothing left are settled."""
        resumed: list[tuple[ShortTermMemory, int]] = []
        for instruction_id, attempts in list(self.owed.items()):
            record = self.journal.instruction(instruction_id)
            stm = record.stm.model_copy(deep=True) if record and record.stm else None
            if stm is not None:
                contents = stm.embodied.locker_contents
                stm.embodied.locker_contents = [i for i in contents if i in in_locker]
            if stm is None or not items_to_return(self.office, stm):
                logger.info("nothing left to give back for %s", instruction_id)
                self.owed.pop(instruction_id)
                continue
            self.owed[instruction_id] = attempts + 1
            resumed.append((stm, attempts + 1))
        return resumed
