"""Admission apart from execution: admitted instructions start in order, one at a time, and
one cancelled while it waits never starts."""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import AsyncIterator
from dataclasses import dataclass
from pathlib import Path

from assistantx.core.office import load_office
from assistantx.core.settings import Settings
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant, InstructionHook
from assistantx.service.admission import HOLD_MAX_S, Admission
from assistantx.sim.office import SimOffice
from assistantx.store.journal import Journal
from helpers.office import sim_assistant
from helpers.office import started as assistant_started
from service.stapler_reasoner import build_factory


@dataclass
class _Rig:
    """The default office's simulated assistant behind an Admission on a fresh journal."""

    sim: SimOffice
    assistant: Assistant
    journal: Journal
    admission: Admission

    @classmethod
    def build(cls, tmp_path: Path, on_start: InstructionHook) -> _Rig:
        office = load_office()
        sim = SimOffice(office)
        assistant = sim_assistant(sim, build_factory(office, Settings()))
        assistant.on_instruction_start(on_start)
        journal = Journal.open(tmp_path / "j.sqlite3")
        return cls(sim, assistant, journal, Admission(assistant, journal))

    @contextlib.asynccontextmanager
    async def running(self) -> AsyncIterator[None]:
        """The locker, the assistant and the admission's starter running; on exit all
        stopped and the journal closed."""
        try:
            async with assistant_started(self.sim, self.assistant):
                self.admission.start()
                try:
                    yield
                finally:
                    await self.admission.stop()
        finally:
            self.journal.close()


async def test_admitted_instructions_start_in_order_and_a_withdrawn_one_never(
    tmp_path: Path,
) -> None:
    started: list[str] = []
    three_started = asyncio.Event()

    async def on_start(stm: ShortTermMemory) -> None:
        started.append(stm.instruction_id)
        if len(started) == 3:
            three_started.set()

    rig = _Rig.build(tmp_path, on_start)
    journal, admission = rig.journal, rig.admission
    records = [
        await journal.acreate_instruction(f"ins-{n}", "lee", "a stapler please", float(n))
        for n in range(4)
    ]
    for record in records:
        admission.admit(record)  # nothing starts before the starter runs
    assert started == [] and admission.waiting == 4
    assert await admission.withdraw("ins-2") is True
    assert await admission.withdraw("ins-9") is False
    async with rig.running():
        with contextlib.suppress(TimeoutError):  # the assert below shows what did start
            await asyncio.wait_for(three_started.wait(), 5)
        assert started == ["ins-0", "ins-1", "ins-3"]
        withdrawn = journal.instruction("ins-2")
        assert withdrawn is not None and withdrawn.status == "cancelled"
        assert admission.waiting == 0


async def test_the_starter_holds_back_while_submissions_arrive_but_not_for_ever(
    tmp_path: Path,
) -> None:
    started: list[str] = []
    one_started = asyncio.Event()

    async def on_start(stm: ShortTermMemory) -> None:
        started.append(stm.instruction_id)
        one_started.set()

    rig = _Rig.build(tmp_path, on_start)
    journal, admission = rig.journal, rig.admission
    async with rig.running():
        with admission.arriving():  # a burst: another submission is being journaled
            admission.admit(await journal.acreate_instruction("ins-0", "lee", "a stapler", 0.0))
            await asyncio.sleep(HOLD_MAX_S / 2)
            assert started == []  # acknowledgements first
            await asyncio.wait_for(one_started.wait(), 5)  # held back at most HOLD_MAX_S
        assert started == ["ins-0"]
        one_started.clear()
        admission.admit(await journal.acreate_instruction("ins-1", "lee", "a stapler", 1.0))
        await asyncio.wait_for(one_started.wait(), 5)  # after a pause: started
        assert started == ["ins-0", "ins-1"]
