"""The LLM path against a real server: llama.cpp's, serving SmolLM2-135M-Instruct.

A 135M model is weak; these tests check the system around it: every agent gets schema-valid
output (the server enforces our grammar-safe schemas), a whole instruction ends with the
requester told in words, nothing ungrounded runs, and every request is counted. The server's
speed is measured first (``server_speed``) and every budget sized from it, so a slow machine
makes the tests check less, never wait minutes: the whole marker keeps to about 5 minutes.
"""

from __future__ import annotations

import json
import subprocess
import time

import pytest
from pydantic import BaseModel

from assistantx.adapters.model import (
    ChatRequest,
    Message,
    OpenAICompatibleModel,
    RetryPolicy,
    StructuredResult,
    UsageLedger,
    structured_call,
)
from assistantx.adapters.model.usage import MeteredModel
from assistantx.agents.base import AgentContext
from assistantx.agents.llm import AgentPrompts, LLMReasonerFactory, agent_call, failed_call
from assistantx.core.actions import Wait
from assistantx.core.errors import ModelBehaviorError
from assistantx.core.office import Office, load_office
from assistantx.core.ports.model import LLMCallFailed
from assistantx.core.structured.schema import grammar_schema
from assistantx.core.trace import (
    Decision,
    Observation,
    Percept,
    Plan,
    Reflection,
    SubGoal,
    Trace,
    TraceStep,
)
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from helpers.office import run_one, sim_assistant
from llm_server.llama_server import MODEL_NAME, LlamaServer
from llm_server.speed import CALL_CAP_S, ServerSpeed, prompt_tokens

pytestmark = pytest.mark.llm_server

AGENT_SCHEMAS: dict[str, type[BaseModel]] = {
    "perception": Percept,
    "planning": Plan,
    "decision": Decision,
    "reflection": Reflection,
}


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def model_for(server: LlamaServer, budget_s: float, **kwargs: object) -> OpenAICompatibleModel:
    """The client with a call budget sized from the measured speed (``server_speed``)."""
    options: dict[str, object] = {
        "timeout_s": budget_s,
        "max_tokens": 160,
        "stream": True,
        "call_budget_s": budget_s,
        "retry": RetryPolicy(max_retries=1, base_delay_s=0.2),
    }
    options.update(kwargs)
    return OpenAICompatibleModel(server.base_url, MODEL_NAME, **options)  # type: ignore[arg-type]


def requests_sent(ledger: UsageLedger) -> int:
    """Every request the ledger's calls sent, refused formats and retries included."""
    return sum(1 + r.retries for r in ledger.records)


def requests_served(server: LlamaServer) -> int:
    """The chat requests the server's own access log shows (answered or refused)."""
    return server.log_tail(10_000_000).count('"POST /v1/chat/completions HTTP/1.1" ')


def context(office: Office, text: str = "Could you get me a stapler, please?") -> AgentContext:
    trace = Trace(instruction_id="ins-r", requester="lee", text=text, reasoner="llm", started_at=0)
    stm = ShortTermMemory(instruction_id="ins-r", requester="lee", text=text, trace=trace)
    stm.embodied.robot_place = "meeting_room"
    stm.trace.steps.append(TraceStep(index=0, started_at=0.0))
    return AgentContext(
        ltm=LongTermMemory(office), stm=stm, resolver=Resolver(office), step=0, now=0.0
    )


def test_every_agent_schema_converts_the_way_llama_cpp_does(llama_server: LlamaServer) -> None:
    # llama-cpp-python's own converter (the one its server runs on response_format.schema);
    # pydantic's raw schemas made grammars with thousands of repetitions and crashed it
    schemas = {name: grammar_schema(model) for name, model in AGENT_SCHEMAS.items()}
    code = (
        "import json, sys\n"
        "from llama_cpp.llama_grammar import json_schema_to_gbnf\n"
        "for name, schema in json.load(sys.stdin).items():\n"
        "    print(name, len(json_schema_to_gbnf(json.dumps(schema))))\n"
    )
    done = subprocess.run(
        [str(llama_server.python), "-c", code],
        input=json.dumps(schemas),
        capture_output=True,
        text=True,
        check=False,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    sizes = dict(line.split() for line in done.stdout.splitlines())
    assert sorted(sizes) == sorted(AGENT_SCHEMAS)
    for name, size in sizes.items():
        assert 0 < int(size) < 20_000, (name, size)
    for schema in schemas.values():
        assert '"maxLength"' not in json.dumps(schema)


class Tiny(BaseModel):
    word: str
    count: int


async def test_a_small_structured_call_is_schema_valid_and_counted(
    llama_server: LlamaServer, server_speed: ServerSpeed
) -> None:
    messages = (
        Message(role="system", content="Answer with JSON: a word and a small number."),
        Message(role="user", content="Give one word and the number 3."),
    )
    budget = server_speed.must_finish_budget_s(prompt_tokens(messages), 40)
    ledger = UsageLedger()
    served_before = requests_served(llama_server)
    # not streamed: llama-cpp-python reports usage on plain answers only
    client = model_for(llama_server, budget, max_tokens=40, stream=False)
    async with MeteredModel(client, ledger) as model:
        request = ChatRequest(messages=messages, agent="tiny")
        result = await structured_call(model, request, Tiny, max_retries=2)
    assert isinstance(result.output, Tiny)
    assert result.attempts[-1].response.structured_mode == "json_object_schema"
    assert not result.usage.estimated  # the server's own counts
    # the refused json_schema request and the answered one(s): counted as the server saw them
    assert requests_sent(ledger) == requests_served(llama_server) - served_before


async def test_each_agent_call_is_schema_valid_or_counted(
    llama_server: LlamaServer, office: Office, server_speed: ServerSpeed
) -> None:
    """The agent with the smallest prompt always, then as many others as the measured speed
    allows in one minute; each one that completes is schema-valid, each one cut off by its
    budget is counted with what it cost. (The other agents' prompts are larger, and on a
    loaded machine none of them fitted two minutes either: the first call is what makes this
    test check something on any machine.)"""
    reasoner = LLMReasonerFactory(
        model_for(llama_server, CALL_CAP_S), AgentPrompts.load(), output_retries=1
    )()
    ctx = context(office)
    percept = Percept(people=["lee", "zhang"], items=["stapler"], summary="lee wants a stapler")
    plan = Plan(goal="get lee a stapler", subgoals=[SubGoal(description="ask zhang")])
    decision = Decision(actions=[Wait(timeout_s=60)])
    messages = {
        "perception": reasoner.perception_messages(ctx),
        "planning": reasoner.planning_messages(ctx, percept),
        "decision": reasoner.decision_messages(ctx, percept, plan),
        "reflection": reasoner.reflection_messages(
            ctx, percept, plan, decision, [], Observation(robot_place="meeting_room")
        ),
    }
    deadline = time.monotonic() + 60.0
    completed: list[str] = []
    called: list[str] = []
    for agent in sorted(AGENT_SCHEMAS, key=lambda a: prompt_tokens(messages[a])):
        size = prompt_tokens(messages[agent])
        left = deadline - time.monotonic()
        if not called:
            budget = server_speed.must_finish_budget_s(size, 160)
        elif server_speed.fits(size, 160, left):
            budget = min(server_speed.budget_s(size, 160), left)
        else:
            continue  # would not finish in what is left of the test's time
        called.append(agent)
        ledger = UsageLedger()
        outcome = await _call(model_for(llama_server, budget), ledger, agent, messages[agent])
        if isinstance(outcome, LLMCallFailed):
            assert outcome.kind == "timed_out", outcome
            call = failed_call(agent, outcome)
            assert call.attempts >= 1 and call.estimated  # counted, marked estimated
            continue
        if isinstance(outcome, ModelBehaviorError):
            assert len(ledger) == 2  # both answers came back, invalid, and were counted
            continue
        assert isinstance(outcome.output, AGENT_SCHEMAS[agent])
        assert outcome.attempts[-1].response.finish_reason != "length"
        assert agent_call(agent, outcome.attempts).attempts == requests_sent(ledger)
        completed.append(agent)
    print(f"called: {called}; completed within budget: {completed}")


async def _call(
    client: OpenAICompatibleModel, ledger: UsageLedger, agent: str, messages: list[Message]
) -> StructuredResult[BaseModel] | LLMCallFailed | ModelBehaviorError:
    """One agent's structured call: its result, or why it gave none."""
    async with MeteredModel(client, ledger) as model:
        request = ChatRequest(messages=tuple(messages), agent=agent)
        try:
            return await structured_call(model, request, AGENT_SCHEMAS[agent], max_retries=1)
        except (LLMCallFailed, ModelBehaviorError) as exc:
            return exc


async def test_a_whole_instruction_with_the_real_model_ends_told_and_counted(
    llama_server: LlamaServer, office: Office, server_speed: ServerSpeed
) -> None:
    ledger = UsageLedger()
    factory_model = MeteredModel(
        model_for(llama_server, server_speed.budget_s(2500, 128), max_tokens=128), ledger
    )
    factory = LLMReasonerFactory(factory_model, AgentPrompts.load(), output_retries=0)
    sim = SimOffice(office, unavailable=("zhang",))
    served_before = requests_served(llama_server)
    assistant = sim_assistant(
        sim, factory, reasoner_name="llm", limits=LoopLimits(max_steps=2, wall_s=120.0)
    )
    try:
        stm = await run_one(sim, assistant, "lee", "Could you get me a stapler, please?")
    finally:
        await factory_model.stop()

    trace = stm.trace
    assert trace.outcome in ("done", "failed", "unachievable")
    told = [m for m in sim.messenger.sent if m.chat.id == "lee"]
    assert told, "the requester was never told"
    final = told[-1].text
    assert "http" not in final.lower() and "Traceback" not in final
    resolver = Resolver(office)
    for result in trace.actions():
        if not result.refused:
            resolver.ground(result.action)  # raises for anything outside memory
    # zhang is away and never answered: no code reached him, whatever the model decided
    assert not any(m.chat.id == "zhang" and "code" in m.text.lower() for m in sim.messenger.sent)
    # every request is in the trace: the ledger's, and one cut off by the wall bound
    assert trace.usage.llm_calls >= requests_sent(ledger) > 0
    assert trace.usage.llm_calls >= requests_served(llama_server) - served_before
