"""One-time codes live only as long as their purpose, checked at a real lock over TCP: a code
whose hand-over timed out, or whose instruction ended or was cancelled, is revoked at the lock
and refused when scanned afterwards."""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import AsyncIterator
from dataclasses import dataclass, field

import pytest

from assistantx.adapters.lock.protocol import LockKeys
from assistantx.adapters.lock.tcp import TcpLocker
from assistantx.agents.base import AgentContext
from assistantx.core.actions import Action, Inquire, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.clock import WallClock
from assistantx.core.events import TraceEvent
from assistantx.core.office import Office, load_office
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.server import LockServer
from assistantx.sim.office import SimOffice
from helpers.office import sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner, Step


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


@dataclass
class Rig:
    assistant: Assistant
    sim: SimOffice
    locker: TcpLocker
    code_sent: asyncio.Event = field(default_factory=asyncio.Event)

    def payload(self, person: str) -> str:
        """The QR payload the assistant sent ``person`` (what their phone shows)."""
        for message in self.sim.messenger.sent:
            for a in message.attachments:
                if message.chat.id == person and a.qr_payload:
                    return a.qr_payload
        raise AssertionError(f"{person} got no code")


@pytest.fixture
async def lock_server() -> AsyncIterator[tuple[LockServer, LockKeys]]:
    keys = LockKeys.from_secret("a secret shared by the lock and the assistant, lifecycle")
    server = LockServer(LockController("locker-q", keys.codes, WallClock()), keys.link_key)
    await server.start()
    try:
        yield server, keys
    finally:
        await server.stop()


def asked(person: str) -> list[Step]:
    """The steps that ask ``person`` first: the loop hands a code only to someone who answered."""
    return [
        [Inquire(contact=person, question="Could you lend Lee your stapler?")],
        [Wait(reason=f"{person}'s answer", timeout_s=600)],
    ]


@dataclass
class Script:
    steps: list[Step]
    unavailable: tuple[str, ...] = ()


@contextlib.asynccontextmanager
async def _rig(
    office: Office, lock: tuple[LockServer, LockKeys], script: Script
) -> AsyncIterator[Rig]:
    server, keys = lock
    host, port = server.address
    locker = TcpLocker(host, port, keys, lock_id="locker-q", render_png=False)
    clock = WallClock(speedup=200)  # real time runs while scans travel over TCP
    sim = SimOffice(office, unavailable=script.unavailable, locker=locker, clock=clock)
    reasoner = ScriptedReasoner(script.steps)
    assistant = sim_assistant(sim, lambda: reasoner)
    rig = Rig(assistant, sim, locker)

    async def watch(event: TraceEvent) -> None:
        result = event.data.get("result")
        if isinstance(result, dict) and result.get("action", {}).get("type") == "send_qr":
            rig.code_sent.set()

    assistant.subscribe(watch)
    await locker.start()
    await assistant.start()
    try:
        yield rig
    finally:
        await assistant.stop()
        await sim.aclose()
        await locker.stop()


async def test_a_timed_out_hand_over_code_is_refused_after_the_instruction(
    office: Office, lock_server: tuple[LockServer, LockKeys]
) -> None:
    seen_after_timeout: list[str] = []

    def after_timeout(ctx: AgentContext) -> list[Stop]:
        seen_after_timeout.extend(c.state for c in ctx.stm.embodied.codes)
        return [Stop(outcome="failed", summary="Wang did not come.")]

    script = Script(
        [
            *asked("wang"),
            # The robot stays in the meeting room: Wang agreed, but does not come there.
            [SendQR(contact="wang", item="stapler:wang")],
            [WaitInPlace(person="wang", timeout_s=60)],
            after_timeout,
        ],
    )
    async with _rig(office, lock_server, script) as rig:
        stm = await rig.assistant.submit("lee", "bring me Wang's stapler")
        stm = await rig.assistant.wait(stm.instruction_id)
        assert stm.trace.outcome == "failed"
        assert seen_after_timeout == ["revoked"]  # withdrawn when the wait timed out
        scan = await rig.locker.simulate_scan(rig.payload("wang"))
        assert (scan.kind, scan.reason) == ("code_rejected", "revoked")
        assert (await rig.locker.status()).active_codes == 0


async def _zhang_has_a_code(rig: Rig) -> ShortTermMemory:
    """Lee asks for Zhang's stapler; the instruction once Zhang's code went out."""
    stm = await rig.assistant.submit("lee", "bring me Zhang's stapler")
    async with asyncio.timeout(10):
        await rig.code_sent.wait()
    return stm


async def _zhangs_code_is_revoked(rig: Rig, stm: ShortTermMemory) -> None:
    """The instruction's one code is revoked, and the lock refuses it when Zhang scans it."""
    assert [c.state for c in stm.embodied.codes] == ["revoked"]
    scan = await rig.locker.simulate_scan(rig.payload("zhang"))
    assert (scan.kind, scan.reason) == ("code_rejected", "revoked")


def _code_to_zhang_then(last: Action) -> Script:
    """Zhang is asked for the stapler, sent a code for it, then the script does ``last``."""
    return Script([*asked("zhang"), [SendQR(contact="zhang", item="stapler:zhang")], [last]])


async def test_an_ended_instructions_unused_code_is_refused(
    office: Office, lock_server: tuple[LockServer, LockKeys]
) -> None:
    script = _code_to_zhang_then(Stop(outcome="done", summary="Never mind."))
    async with _rig(office, lock_server, script) as rig:
        stm = await rig.assistant.submit("lee", "bring me Zhang's stapler")
        stm = await rig.assistant.wait(stm.instruction_id)
        await _zhangs_code_is_revoked(rig, stm)


async def test_a_cancelled_instructions_code_is_refused(
    office: Office, lock_server: tuple[LockServer, LockKeys]
) -> None:
    script = _code_to_zhang_then(Wait(reason="a long wait", timeout_s=3600))
    async with _rig(office, lock_server, script) as rig:
        stm = await _zhang_has_a_code(rig)
        assert [c.state for c in stm.embodied.codes] == ["issued"]
        assert rig.assistant.cancel(stm.instruction_id)
        with pytest.raises(asyncio.CancelledError):
            await rig.assistant.wait(stm.instruction_id)
        await _zhangs_code_is_revoked(rig, stm)


async def test_a_shutdown_keeps_the_codes_of_instructions_that_will_resume(
    office: Office, lock_server: tuple[LockServer, LockKeys]
) -> None:
    script = _code_to_zhang_then(Wait(reason="a long wait", timeout_s=3600))
    async with _rig(office, lock_server, script) as rig:
        stm = await _zhang_has_a_code(rig)
        await rig.assistant.stop()
        assert [c.state for c in stm.embodied.codes] == ["issued"]
        assert (await rig.locker.status()).active_codes == 1
