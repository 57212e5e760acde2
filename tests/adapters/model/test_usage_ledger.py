"""Usage accounting: per agent, per step, per instruction, and the metered wrapper."""

from __future__ import annotations

import json

import pytest
from pydantic import BaseModel

from assistantx.adapters.model import (
    CallRecord,
    ChatRequest,
    ChatResponse,
    Message,
    MeteredModel,
    OpenAICompatibleModel,
    RetryPolicy,
    Usage,
    UsageLedger,
    structured_call,
)
from fakes.scripted_llm import Reply, ScriptedLLM, json_reply, rate_limited


def request(agent: str, instruction: str | None, step: int | None, attempt: int = 0) -> ChatRequest:
    return ChatRequest(
        messages=(Message(role="user", content="hi"),),
        agent=agent,
        instruction_id=instruction,
        step=step,
        attempt=attempt,
    )


def response(
    prompt: int, completion: int, latency: float, *, estimated: bool = False
) -> ChatResponse:
    return ChatResponse(
        text="x",
        usage=Usage(prompt_tokens=prompt, completion_tokens=completion, estimated=estimated),
        latency_s=latency,
        model="m",
        retries=1 if estimated else 0,
    )


@pytest.fixture
def ledger() -> UsageLedger:
    ledger = UsageLedger()
    ledger.record(request("perception", "i1", 1), response(100, 10, 0.5))
    ledger.record(request("planning", "i1", 1), response(200, 20, 1.0))
    ledger.record(request("planning", "i1", 1, attempt=1), response(250, 25, 1.5))
    ledger.record(request("perception", "i1", 2), response(120, 12, 0.25, estimated=True))
    ledger.record(request("perception", "i2", 1), response(90, 9, 0.75))
    ledger.record(request("react", None, None), response(5, 5, 0.125))
    return ledger


def test_totals(ledger: UsageLedger) -> None:
    totals = ledger.totals()
    assert totals.calls == 6
    assert totals.prompt_tokens == 765
    assert totals.completion_tokens == 81
    assert totals.total_tokens == 846
    assert totals.latency_s == pytest.approx(4.125)
    assert totals.repairs == 1
    assert totals.estimated_calls == 1
    assert totals.retries == 1


def test_by_agent(ledger: UsageLedger) -> None:
    by_agent = ledger.by_agent()
    assert set(by_agent) == {"perception", "planning", "react"}
    assert by_agent["planning"].calls == 2
    assert by_agent["planning"].prompt_tokens == 450
    assert by_agent["perception"].completion_tokens == 31
    assert ledger.by_agent("i2") == {"perception": ledger.totals(instruction_id="i2")}


def test_by_step_and_instruction(ledger: UsageLedger) -> None:
    steps = ledger.by_step("i1")
    assert list(steps) == [1, 2]
    assert steps[1].calls == 3
    assert steps[1].prompt_tokens == 550
    assert steps[2].prompt_tokens == 120
    instructions = ledger.by_instruction()
    assert set(instructions) == {"i1", "i2"}  # the call outside any instruction is not here
    assert instructions["i1"].calls == 4


def test_json_round_trip(ledger: UsageLedger) -> None:
    data = json.loads(ledger.to_json())
    assert data["totals"]["calls"] == 6
    assert data["by_agent"]["planning"]["prompt_tokens"] == 450
    assert data["by_instruction"]["i1"]["by_step"]["1"]["calls"] == 3
    assert data["by_instruction"]["i1"]["by_agent"]["perception"]["calls"] == 2
    assert len(data["calls"]) == 6
    again = UsageLedger.from_dict(data)
    assert again.records == ledger.records
    assert again.to_dict() == ledger.to_dict()


def test_from_dict_rejects_garbage() -> None:
    with pytest.raises(TypeError, match="calls"):
        UsageLedger.from_dict({"totals": {}})
    with pytest.raises(ValueError, match="prompt_tokens"):
        UsageLedger.from_dict({"calls": [{"agent": "a", "prompt_tokens": -1}]})


class Answer(BaseModel):
    answer: str


async def test_metered_model_records_every_call(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script(
        "decision",
        rate_limited(0),
        Reply(content="not json", usage={"prompt_tokens": 30, "completion_tokens": 3}),
        json_reply({"answer": "yes"}, usage=None),
    )
    ledger = UsageLedger()
    inner = OpenAICompatibleModel(
        scripted_llm.base_url, "m", retry=RetryPolicy(max_retries=2, base_delay_s=0.001)
    )
    async with MeteredModel(inner, ledger) as model:
        assert inner.started
        req = request("decision", "i9", 4)
        result = await structured_call(model, req, Answer)
    assert not inner.started
    assert result.output.answer == "yes"
    records = ledger.records
    assert [(r.agent, r.instruction_id, r.step, r.attempt) for r in records] == [
        ("decision", "i9", 4, 0),
        ("decision", "i9", 4, 1),
    ]
    assert records[0] == CallRecord(
        agent="decision",
        instruction_id="i9",
        step=4,
        model="m",
        prompt_tokens=30,
        completion_tokens=3,
        latency_s=records[0].latency_s,
        retries=1,
        attempt=0,
        estimated=False,
    )
    assert records[1].estimated
    assert ledger.totals().repairs == 1


async def test_a_failed_call_is_recorded_with_its_cost() -> None:
    from assistantx.adapters.model import ChatModel, ChatRequest, Message, MeteredModel
    from assistantx.core.ports.model import LLMCallFailed, Usage

    class _TimesOut(ChatModel):
        async def _complete(self, request: ChatRequest) -> ChatResponse:
            raise LLMCallFailed(
                "timed out",
                user_text="my language model server took too long to answer",
                usage=Usage(prompt_tokens=700, completion_tokens=30, estimated=True),
                latency_s=2.5,
                model="m",
            )

    ledger = UsageLedger()
    request = ChatRequest(messages=(Message(role="user", content="hi"),), agent="decision")
    async with MeteredModel(_TimesOut(), ledger) as model:
        with pytest.raises(LLMCallFailed):
            await model.complete(request)
    (record,) = ledger.records
    assert record.failed
    assert (record.prompt_tokens, record.completion_tokens, record.latency_s) == (700, 30, 2.5)
    assert ledger.totals().calls == 1
