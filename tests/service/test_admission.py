"""Admission apart from execution: admitted instructions start in order, one at a time, and
one cancelled while it waits never starts."""

from __future__ import annotations

import asyncio
import contextlib
from pathlib import Path

from assistantx.core.office import load_office
from assistantx.core.settings import Settings
from assistantx.memory.short_term import ShortTermMemory
from assistantx.service.admission import HOLD_MAX_S, Admission
from assistantx.sim.office import SimOffice
from assistantx.store.journal import Journal
from helpers.office import sim_assistant
from service.stapler_reasoner import build_factory


async def test_admitted_instructions_start_in_order_and_a_withdrawn_one_never(
    tmp_path: Path,
) -> None:
    office = load_office()
    sim = SimOffice(office)
    assistant = sim_assistant(sim, build_factory(office, Settings()))
    started: list[str] = []
    three_started = asyncio.Event()

    async def on_start(stm: ShortTermMemory) -> None:
        started.append(stm.instruction_id)
        if len(started) == 3:
            three_started.set()

    assistant.on_instruction_start(on_start)
    journal = Journal.open(tmp_path / "j.sqlite3")
    admission = Admission(assistant, journal)
    records = [
        await journal.acreate_instruction(f"ins-{n}", "lee", "a stapler please", float(n))
        for n in range(4)
    ]
    for record in records:
        admission.admit(record)  # nothing starts before the starter runs
    assert started == [] and admission.waiting == 4
    assert await admission.withdraw("ins-2") is True
    assert await admission.withdraw("ins-9") is False
    await sim.locker.start()
    await assistant.start()
    admission.start()
    try:
        with contextlib.suppress(TimeoutError):  # the assert below shows what did start
            await asyncio.wait_for(three_started.wait(), 5)
        assert started == ["ins-0", "ins-1", "ins-3"]
        withdrawn = journal.instruction("ins-2")
        assert withdrawn is not None and withdrawn.status == "cancelled"
        assert admission.waiting == 0
    finally:
        await admission.stop()
        await assistant.stop()
        await sim.locker.stop()
        journal.close()


async def test_the_starter_holds_back_while_submissions_arrive_but_not_for_ever(
    tmp_path: Path,
) -> None:
    office = load_office()
    sim = SimOffice(office)
    assistant = sim_assistant(sim, build_factory(office, Settings()))
    started: list[str] = []
    one_started = asyncio.Event()

    async def on_start(stm: ShortTermMemory) -> None:
        started.append(stm.instruction_id)
        one_started.set()

    assistant.on_instruction_start(on_start)
    journal = Journal.open(tmp_path / "j.sqlite3")
    admission = Admission(assistant, journal)
    await sim.locker.start()
    await assistant.start()
    admission.start()
    try:
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
    finally:
        await admission.stop()
        await assistant.stop()
        await sim.locker.stop()
        journal.close()
