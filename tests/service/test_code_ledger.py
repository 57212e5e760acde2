"""A scan the lock reports is journaled with the world it changed before anyone acts on it:
queued ahead of their writes on the event loop, without holding the loop for the commit."""

from __future__ import annotations

from pathlib import Path

from assistantx.core.clock import SimClock
from assistantx.core.events import TraceEvent
from assistantx.core.ports.lock import LockEvent
from assistantx.service.code_ledger import LEDGER_STATE, CodeLedger
from assistantx.store.journal import Journal


async def test_a_scan_is_queued_with_the_world_ahead_of_what_acts_on_it(tmp_path: Path) -> None:
    journal = Journal.open(tmp_path / "journal.sqlite3")
    try:
        ledger = CodeLedger(
            journal, SimClock(start=100.0), 900, world_state=lambda: {"sim_world": {"v": 2}}
        )
        scanned = LockEvent(seq=1, kind="code_accepted", time=100.0, code_id="c1")
        ledger.on_lock_event(scanned)
        assert ledger.ended("c1") == "scanned"
        assert journal.state(LEDGER_STATE) is None  # queued, not waited for
        acted = TraceEvent(instruction_id="ins-1", kind="action_result", time=101.0, step=1)
        await journal.arecord(acted)  # the instruction's record of what it did next
        assert journal.state(LEDGER_STATE) == {"codes": {"c1": ["scanned", 1000.0]}, "minted": {}}
        assert journal.state("sim_world") == {"v": 2}
        ledger.on_lock_event(scanned)  # reported again: nothing new to journal
        closed = LockEvent(seq=2, kind="door_closed", time=102.0, code_id="c1")
        ledger.on_lock_event(closed)
        await journal.arecord(acted)
        assert CodeLedger(journal, SimClock(start=100.0), 900).ended("c1") == "used"
    finally:
        journal.close()
