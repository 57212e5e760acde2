"""The LLM path against a real server: llama.cpp's, serving SmolLM2-135M-Instruct.

A 135M model is weak; these tests check the system around it: every agent gets schema-valid
output (the server enforces our grammar-safe schemas), a whole instruction ends with the
requester told in words, nothing ungrounded runs, and every request is counted.
"""

from __future__ import annotations

import json
import subprocess

import pytest
from pydantic import BaseModel

from assistantx.adapters.model import (
    ChatRequest,
    OpenAICompatibleModel,
    UsageLedger,
    structured_call,
)
from assistantx.adapters.model.usage import MeteredModel
from assistantx.agents.base import AgentContext
from assistantx.agents.llm import AgentPrompts, LLMReasonerFactory
from assistantx.core.actions import Wait
from assistantx.core.office import Office, load_office
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


def model_for(server: LlamaServer, **kwargs: object) -> OpenAICompatibleModel:
    # generous budgets: on a 2-core CI machine shared with other jobs a 2k-token prompt of
    # this model took minutes; the budgets bound a hung server, not a slow one
    options: dict[str, object] = {
        "timeout_s": 600.0,
        "max_tokens": 160,
        "stream": True,
        "call_budget_s": 600.0,
    }
    options.update(kwargs)
    return OpenAICompatibleModel(server.base_url, MODEL_NAME, **options)  # type: ignore[arg-type]


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


async def test_each_agent_call_returns_schema_valid_output(
    llama_server: LlamaServer, office: Office
) -> None:
    ledger = UsageLedger()
    model = MeteredModel(model_for(llama_server), ledger)
    factory = LLMReasonerFactory(model, AgentPrompts.load(), output_retries=2)
    reasoner = factory()
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
    async with model:
        for agent, output_type in AGENT_SCHEMAS.items():
            request = ChatRequest(messages=tuple(messages[agent]), agent=agent)
            result = await structured_call(model, request, output_type, max_retries=2)
            assert isinstance(result.output, output_type)
            last = result.attempts[-1].response
            # the first mode llama-cpp-python accepts: the schema goes in as a grammar
            assert last.structured_mode == "json_object_schema"
            assert last.finish_reason != "length"
    # every request counted, the refused json_schema one aside (it generated nothing)
    assert len(ledger) >= 4
    assert all(r.prompt_tokens > 0 for r in ledger.records)


async def test_a_whole_instruction_with_the_real_model_ends_told_and_counted(
    llama_server: LlamaServer, office: Office
) -> None:
    ledger = UsageLedger()
    model = MeteredModel(model_for(llama_server, max_tokens=128), ledger)
    factory = LLMReasonerFactory(model, AgentPrompts.load(), output_retries=0)
    sim = SimOffice(office, unavailable=("zhang",))
    assistant = sim_assistant(
        sim, factory, reasoner_name="llm", limits=LoopLimits(max_steps=2, wall_s=900.0)
    )
    try:
        stm = await run_one(sim, assistant, "lee", "Could you get me a stapler, please?")
    finally:
        await model.stop()

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
    # every request the server answered or failed is in the trace
    assert trace.usage.llm_calls >= len(ledger) > 0
    assert trace.usage.prompt_tokens >= sum(r.prompt_tokens for r in ledger.records) > 0
