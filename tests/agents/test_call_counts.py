"""Every request a reasoner sends is counted in its trace, in every reasoner that calls a
model: the scripted server counts what it received and the trace must say the same, when
the answers are unusable (repairs), when a request times out after a repair, and when the
server refuses the connection (tries that never reached it: counted, at no tokens)."""

from __future__ import annotations

import asyncio
from typing import Any

import pytest

from assistantx.adapters.model.openai_compat import OpenAICompatibleModel
from assistantx.agents.registry import LLM_REASONERS, reasoner_factory
from assistantx.core.http_retry import RetryPolicy
from assistantx.core.office import Office, load_office
from assistantx.core.trace import Trace
from assistantx.sim.office import SimOffice
from fakes.fixtures import scripted_llm  # noqa: F401
from fakes.scripted_llm import RecordedRequest, Reply, ScriptedLLM, malformed_json, slow
from helpers.llm_office import llm_settings, make_assistant
from helpers.office import run_one
from helpers.servers import refusing_port

# unsure for the embedded reader, so the cascade calls the model too
TEXT = "bring me the thing"
REASONERS = sorted(LLM_REASONERS)
SETTINGS: dict[str, Any] = {"llm_timeout_s": 0.5, "llm_max_retries": 2, "llm_output_retries": 1}


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def _trace(office: Office, llm: ScriptedLLM, name: str, **overrides: Any) -> Trace:
    values = {**SETTINGS, **overrides}
    settings = llm_settings(llm, **values)
    # The client as the composition root builds it, with the same number of retries, only
    # 10 ms apart instead of the backoff's 0.5 s and more: what is counted is the same, and
    # the refused-connection case no longer sleeps a second per reasoner.
    retry = RetryPolicy(max_retries=settings.llm_max_retries, base_delay_s=0.01, max_delay_s=0.01)
    model = OpenAICompatibleModel.from_settings(settings, retry=retry)
    factory = reasoner_factory(name, office, settings, model=model)
    sim = SimOffice(office)
    assistant = make_assistant(office, sim, factory, max_steps=2)  # type: ignore[arg-type]
    try:
        stm = await run_one(sim, assistant, "lee", TEXT)
    finally:
        await model.stop()
    return stm.trace


def test_every_reasoner_that_calls_a_model_is_covered() -> None:
    assert {"llm", "hybrid", "cascade", "direct", "react", "mobile_agent_v2"} <= set(REASONERS)


@pytest.mark.parametrize("name", REASONERS)
async def test_unusable_answers_and_their_repairs_are_all_counted(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
    name: str,
) -> None:
    scripted_llm.respond_with(lambda _r: malformed_json())
    trace = await _trace(office, scripted_llm, name)

    assert scripted_llm.requests  # the model was asked
    assert trace.usage.llm_calls == len(scripted_llm.requests)


# a timeout a loaded machine's connect and first answer fit in (0.5 s did not, at load 20),
# the repair still never back within it; no retries of the timed-out request, so the wait is
# one timeout per call
REPAIR_TIMEOUT = {"llm_timeout_s": 1.5, "llm_max_retries": 0}


@pytest.fixture(scope="module")
def timed_out_after_a_repair(office: Office) -> dict[str, tuple[int, Trace] | BaseException]:
    """Per reasoner: how many requests its scripted server received, and its trace, for a
    request whose first answer is unusable and whose repair never comes back in time; or
    what the run raised. Each reasoner has its own server and client, as in a test of its
    own; they run side by side, each started once the one before has sent its repair, so
    while a reasoner waits for an answer that must come in time, the others only wait out
    their timeouts (one after the other, the eight waits took 12 s)."""
    return asyncio.run(_timed_out_after_a_repair(office))


async def _timed_out_after_a_repair(
    office: Office,
) -> dict[str, tuple[int, Trace] | BaseException]:
    results: dict[str, tuple[int, Trace] | BaseException] = {}

    async def run(name: str, after: asyncio.Event, repair_sent: asyncio.Event) -> None:
        await after.wait()
        try:
            async with ScriptedLLM() as llm:

                def answer(_request: RecordedRequest) -> Reply:
                    # the first answer is unusable, the repair never comes back in time
                    if len(llm.requests) == 1:
                        return malformed_json()
                    repair_sent.set()
                    return slow(30)

                llm.respond_with(answer)
                trace = await _trace(office, llm, name, **REPAIR_TIMEOUT)
                results[name] = (len(llm.requests), trace)
        except Exception as exc:
            results[name] = exc
        finally:
            repair_sent.set()  # the next one starts, whatever became of this one

    events = [asyncio.Event() for _ in range(len(REASONERS) + 1)]
    events[0].set()
    await asyncio.gather(*(run(name, events[n], events[n + 1]) for n, name in enumerate(REASONERS)))
    return results


@pytest.mark.shares_worker("timed_out_after_a_repair")  # the module fixture, built once
@pytest.mark.parametrize("name", REASONERS)
def test_a_request_that_timed_out_after_a_repair_is_counted(
    timed_out_after_a_repair: dict[str, tuple[int, Trace] | BaseException], name: str
) -> None:
    result = timed_out_after_a_repair[name]
    if isinstance(result, BaseException):
        raise result
    requests, trace = result

    assert requests >= 2
    assert trace.usage.llm_calls == requests
    assert trace.usage.estimated  # what the timed-out request cost is an estimate


@pytest.mark.parametrize("name", REASONERS)
async def test_refused_connections_are_counted_as_tries_at_no_tokens(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
    name: str,
) -> None:
    with refusing_port() as port:
        nowhere = f"http://127.0.0.1:{port}/v1"
        trace = await _trace(office, scripted_llm, name, llm_base_url=nowhere)

    assert scripted_llm.requests == []
    # one request and its two retries, none of which reached a server
    assert trace.usage.llm_calls == 1 + SETTINGS["llm_max_retries"]
    assert (trace.usage.prompt_tokens, trace.usage.completion_tokens) == (0, 0)
