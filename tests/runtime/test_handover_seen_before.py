"""A hand-over the lock reported while no instruction watched (before a restart, with the
code ledger's reports restored into ``Locker.code_states``) is a hand-over done: waiting for
it again would only time out, revoke the code and send the person a new one."""

from __future__ import annotations

from collections.abc import AsyncIterator

import pytest

from assistantx.core.actions import WaitInPlace
from assistantx.core.office import Office, load_office
from assistantx.core.trace import Trace
from assistantx.memory.short_term import IssuedCode, ShortTermMemory
from assistantx.runtime.executors import Executor
from assistantx.sim.office import SimOffice
from helpers.office import sim_executor


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


retired: list[str] = []  # what the executor journaled as revoked (the service's ledger)


@pytest.fixture
async def executor(office: Office) -> AsyncIterator[Executor]:
    retired.clear()

    async def retire(code_ids: list[str]) -> None:
        retired.extend(code_ids)

    async with sim_executor(SimOffice(office), retire_codes=retire) as made:
        yield made


def memory() -> ShortTermMemory:
    trace = Trace(instruction_id="i-7", requester="lee", text="x", reasoner="t", started_at=0)
    stm = ShortTermMemory(instruction_id="i-7", requester="lee", text="x", trace=trace)
    stm.embodied.codes.append(
        IssuedCode(code_id="c-1", person="zhang", item="stapler:zhang", purpose="deposit")
    )
    return stm


async def test_a_deposit_the_lock_reported_before_counts_at_once(executor: Executor) -> None:
    executor.ctx.locker.code_states["c-1"] = "used"
    stm = memory()
    started = executor.ctx.clock.now()
    result = await executor.execute(stm, WaitInPlace(person="zhang", timeout_s=300), key="s1a0")
    assert result.ok, result.observation
    assert executor.ctx.clock.now() == started  # no waiting, no time-out, no revocation
    assert stm.embodied.codes[0].state == "used"
    assert retired == []
    assert stm.embodied.locker_contents == ["stapler:zhang"]


async def test_without_a_report_the_wait_times_out_and_the_code_is_retired(
    executor: Executor,
) -> None:
    """Retired in the journal before the lock is asked, also when the lock has nothing to
    withdraw (here it never knew the code)."""
    stm = memory()
    result = await executor.execute(stm, WaitInPlace(person="zhang", timeout_s=60), key="s1a0")
    assert not result.ok and "did not come" in result.observation
    assert retired == ["c-1"]
