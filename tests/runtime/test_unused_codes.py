"""One rule decides whether a locker code is still unused (``IssuedCode.unused``): sent, and
neither scanned, used nor revoked, by the instruction's view or by what the lock reported since.
Each place that used to decide it on its own follows it: the executor's resend guard and its
revocation, the LLM decision check, the symbolic evidence, and the dashboard's codes panel."""

from __future__ import annotations

from collections.abc import AsyncIterator

import pytest

from assistantx.agents.llm import check_actions
from assistantx.agents.symbolic.evidence import gather
from assistantx.core.actions import SendQR
from assistantx.core.errors import ModelOutputError
from assistantx.core.office import Office, load_office
from assistantx.core.trace import Trace
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import IssuedCode, ShortTermMemory
from assistantx.runtime.executors import Executor
from assistantx.sim.office import SimOffice
from helpers.consent_memory import exchange
from helpers.office import sim_executor

SEND = SendQR(contact="zhang", item="stapler:zhang", purpose="deposit")

# (how the code stands, what the lock reported of it, still unused?)
CASES = [
    ({}, None, True),
    ({"scanned": True}, None, False),
    ({"used": True, "scanned": True}, None, False),
    ({"revoked": True}, None, False),
    ({}, "scanned", False),  # the lock saw the scan before the instruction looked
    ({}, "used", False),
]
IDS = ["issued", "scanned", "used", "revoked", "lock-saw-scan", "lock-saw-use"]


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def memory(**flags: bool) -> ShortTermMemory:
    trace = Trace(instruction_id="i-5", requester="lee", text="x", reasoner="t", started_at=0)
    stm = ShortTermMemory(instruction_id="i-5", requester="lee", text="x", trace=trace)
    # Zhang agreed in his own chat: the consent guard lets his stapler's codes go out.
    stm.dialogue += exchange("zhang", "Lend Lee your stapler?", "Yes.", question_id="q-1")
    stm.embodied.codes.append(
        IssuedCode(code_id="c-1", person="zhang", item="stapler:zhang", purpose="deposit", **flags)
    )
    return stm


@pytest.mark.parametrize(("flags", "reported", "unused"), CASES, ids=IDS)
def test_the_one_rule(flags: dict[str, bool], reported: str | None, unused: bool) -> None:
    code = memory(**flags).embodied.codes[0]
    lock = {"c-1": reported} if reported else {}
    assert code.unused(lock) is unused  # type: ignore[arg-type]
    assert (code.current_state(lock) == "issued") is unused  # type: ignore[arg-type]


# -- the executor (runtime) ----------------------------------------------------------------


@pytest.fixture
async def executor(office: Office) -> AsyncIterator[Executor]:
    async with sim_executor(SimOffice(office)) as made:
        yield made


@pytest.mark.parametrize(("flags", "reported", "unused"), CASES, ids=IDS)
async def test_the_executor_resends_only_when_no_unused_code_is_held(
    flags: dict[str, bool], reported: str | None, unused: bool, executor: Executor
) -> None:
    stm = memory(**flags)
    if reported:
        executor.ctx.locker.code_states["c-1"] = reported  # type: ignore[assignment]
    result = await executor.execute(stm, SEND, key="0:0")
    assert result.ok is not unused
    assert ("already holds an unused QR code" in result.observation) is unused
    assert len(stm.embodied.codes) == (1 if unused else 2)


async def test_the_executor_revokes_exactly_the_unused_codes(executor: Executor) -> None:
    stm = memory(revoked=True)  # a placeholder, never issued at the lock
    first = await executor.execute(stm, SEND, key="0:0")
    again = SendQR(contact="zhang", item="stapler:zhang", purpose="collect")
    second = await executor.execute(stm, again, key="0:1")
    assert first.ok and second.ok
    collect = stm.embodied.codes[2]
    executor.ctx.locker.code_states[collect.code_id] = "scanned"  # seen by the lock only

    assert await executor.revoke_codes(stm) == 1
    assert [c.revoked for c in stm.embodied.codes] == [True, True, False]


# -- the agents ------------------------------------------------------------------------------


@pytest.mark.parametrize(("flags", "unused"), [(c[0], c[2]) for c in CASES if c[1] is None])
def test_the_llm_check_refuses_a_resend_only_of_an_unused_code(
    flags: dict[str, bool], unused: bool, office: Office
) -> None:
    stm = memory(**flags)
    if unused:
        with pytest.raises(ModelOutputError, match="already holds an unused QR code"):
            check_actions([SEND], Resolver(office), stm)
    else:
        check_actions([SEND], Resolver(office), stm)


@pytest.mark.parametrize(("flags", "unused"), [(c[0], c[2]) for c in CASES if c[1] is None])
def test_the_symbolic_evidence_holds_only_unused_codes(
    flags: dict[str, bool], unused: bool, office: Office
) -> None:
    evidence = gather(memory(**flags), office)
    assert evidence.holds_code("zhang", "stapler:zhang", "deposit") is unused
    assert not evidence.holds_code("zhang", "stapler:zhang", "collect")
