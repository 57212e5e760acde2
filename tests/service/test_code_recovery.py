"""The start-up settlement with a networked lock (real sockets): a code still active at the
lock whose instruction the journal says has ended (the process died between journaling the
end and revoking) is withdrawn before anything restarts; a code of an instruction that
resumes stays open; and the journal's ledger remembers what was withdrawn."""

from __future__ import annotations

from pathlib import Path

from assistantx.adapters.lock.protocol import LockKeys
from assistantx.adapters.lock.tcp import TcpLocker
from assistantx.core.clock import SimClock
from assistantx.core.trace import Trace
from assistantx.memory.short_term import IssuedCode, ShortTermMemory
from assistantx.service.code_ledger import CodeLedger
from assistantx.service.code_recovery import settle_codes
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.server import LockServer
from assistantx.store.journal import Journal, Status


def _journaled(journal: Journal, iid: str, code_id: str, status: Status) -> None:
    trace = Trace(instruction_id=iid, requester="lee", text="x", reasoner="t", started_at=0)
    stm = ShortTermMemory(instruction_id=iid, requester="lee", text="x", trace=trace)
    stm.embodied.codes.append(
        IssuedCode(code_id=code_id, person="wang", item="stapler:wang", purpose="deposit")
    )
    journal.checkpoint(stm, status)


async def test_an_ended_instructions_code_is_withdrawn_and_a_live_one_kept(
    tmp_path: Path,
) -> None:
    keys = LockKeys.from_secret("a secret shared by the lock and the assistant, recovery")
    clock = SimClock(start=1_000.0)
    server = LockServer(LockController("locker-r", keys.codes, clock), keys.link_key)
    host, port = await server.start()
    journal = Journal.open(tmp_path / "journal.sqlite3")
    try:
        async with TcpLocker(host, port, keys, clock=clock, render_png=False) as locker:
            ended = await locker.issue_code(
                instruction_id="ins-ended", person="wang", purpose="deposit", item="stapler:wang"
            )
            live = await locker.issue_code(
                instruction_id="ins-live", person="wang", purpose="deposit", item="stapler:wang"
            )
            _journaled(journal, "ins-ended", ended.code_id, "cancelled")
            _journaled(journal, "ins-live", live.code_id, "running")
            ledger = CodeLedger(journal, clock, lifetime_s=900)
            settled = await settle_codes(
                journal,
                ledger,
                locker,
                keys.codes,
                [ended.payload, live.payload],
                clock.now(),
                900,
            )
            assert settled.withdrawn == {ended.code_id}
            assert settled.live == {live.payload}
            refused = await locker.simulate_scan(ended.payload)
            assert (refused.kind, refused.reason) == ("code_rejected", "revoked")
            assert (await locker.simulate_scan(live.payload)).kind == "code_accepted"
        assert CodeLedger(journal, clock, lifetime_s=900).ended(ended.code_id) == "revoked"
    finally:
        journal.close()
        await server.stop()
