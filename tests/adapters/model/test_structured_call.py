"""structured_call: parse, validate, feed errors back, give up with ModelBehaviorError."""

from __future__ import annotations

import json

import pytest
from pydantic import BaseModel, Field

from assistantx.adapters.model import (
    Attempt,
    ChatRequest,
    Message,
    OpenAICompatibleModel,
    RetryPolicy,
    structured_call,
)
from assistantx.core.errors import LLMError, ModelBehaviorError, ModelOutputError
from assistantx.core.structured.schema import grammar_schema
from fakes.scripted_llm import (
    RecordedRequest,
    Reply,
    ScriptedLLM,
    json_reply,
    malformed_json,
    prose_around,
    server_error,
)

KNOWN_PEOPLE = {"lee", "zhang"}


class SubGoal(BaseModel):
    description: str = Field(min_length=1)


class PlanOut(BaseModel):
    goal: str
    subgoals: list[SubGoal] = Field(min_length=1)
    contact: str


def grounded(plan: PlanOut) -> None:
    if plan.contact not in KNOWN_PEOPLE:
        raise ModelOutputError(f"no person named {plan.contact!r} in memory; known: lee, zhang")


GOOD = {"goal": "get the file", "subgoals": [{"description": "ask lee"}], "contact": "lee"}


def planning_request() -> ChatRequest:
    return ChatRequest(
        messages=(
            Message(role="system", content="AGENT: planning\nPlan the task."),
            Message(role="user", content="Get Lee's file."),
        ),
        agent="planning",
        instruction_id="i-1",
        step=3,
    )


def model_for(server: ScriptedLLM) -> OpenAICompatibleModel:
    return OpenAICompatibleModel(
        server.base_url, "m", retry=RetryPolicy(max_retries=1, base_delay_s=0.001)
    )


async def test_valid_first_answer(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", json_reply(GOOD))
    async with model_for(scripted_llm) as model:
        result = await structured_call(model, planning_request(), PlanOut, grounded)
    assert result.output == PlanOut.model_validate(GOOD)
    assert result.repairs == 0
    assert len(result.attempts) == 1
    # The schema went with the request, named after the output type.
    sent = scripted_llm.requests[0].response_format
    assert sent is not None
    assert sent["json_schema"]["name"] == "PlanOut"
    assert sent["json_schema"]["schema"] == grammar_schema(PlanOut)


async def test_prose_and_fences_around_json_are_tolerated(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", prose_around(GOOD))
    async with model_for(scripted_llm) as model:
        result = await structured_call(model, planning_request(), PlanOut)
    assert result.output.contact == "lee"
    assert result.repairs == 0


async def test_malformed_json_is_repaired_with_the_error_fed_back(
    scripted_llm: ScriptedLLM,
) -> None:
    scripted_llm.script("planning", malformed_json(), json_reply(GOOD))
    async with model_for(scripted_llm) as model:
        result = await structured_call(model, planning_request(), PlanOut, max_retries=2)
    assert result.output.goal == "get the file"
    assert result.repairs == 1
    first_error = result.attempts[0].error
    assert first_error is not None
    # finish_reason "length": the answer is rejected whole, never parsed as a partial one
    assert first_error.startswith("the answer was cut off at the length limit")
    second = scripted_llm.requests[1]
    # The original conversation, then one user turn with the error and a short excerpt.
    assert len(second.messages) == 3
    assert first_error in second.last_user_text
    assert (malformed_json().content or "").strip() in second.last_user_text
    assert second.messages[:2] == scripted_llm.requests[0].messages[:2]


async def test_schema_violation_is_fed_back_field_by_field(scripted_llm: ScriptedLLM) -> None:
    bad = {"goal": "x", "subgoals": [], "contact": 5}
    scripted_llm.script("planning", json_reply(bad), json_reply(GOOD))
    async with model_for(scripted_llm) as model:
        result = await structured_call(model, planning_request(), PlanOut)
    error = result.attempts[0].error
    assert error is not None
    assert "subgoals: List should have at least 1 item" in error
    assert "contact: Input should be a valid string (got 5)" in error
    assert error in scripted_llm.requests[1].last_user_text


async def test_grounding_error_is_fed_back(scripted_llm: ScriptedLLM) -> None:
    ungrounded = {**GOOD, "contact": "wang"}
    scripted_llm.script("planning", json_reply(ungrounded), json_reply(GOOD))
    async with model_for(scripted_llm) as model:
        result = await structured_call(model, planning_request(), PlanOut, grounded)
    assert result.output.contact == "lee"
    assert "no person named 'wang' in memory" in scripted_llm.requests[1].last_user_text


async def test_gives_up_with_model_behavior_error(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", "I cannot help with that.", malformed_json(), "{}")
    async with model_for(scripted_llm) as model:
        with pytest.raises(ModelBehaviorError) as caught:
            await structured_call(model, planning_request(), PlanOut, max_retries=2)
    error = caught.value
    assert len(error.attempts) == 3
    assert "goal: Field required" in error.last_error
    assert "after 3 attempt(s)" in str(error)
    attempts = [a for a in error.attempts if isinstance(a, Attempt)]
    assert [a.text for a in attempts] == [
        "I cannot help with that.",
        malformed_json().content,
        "{}",
    ]
    assert all(a.error for a in attempts)
    assert len(scripted_llm.requests) == 3
    # Each retry is the original conversation plus one repair turn: repairs never pile up.
    assert [len(r.messages) for r in scripted_llm.requests] == [2, 3, 3]


async def test_usage_and_latency_are_summed_over_attempts(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script(
        "planning",
        Reply(content="nope", usage={"prompt_tokens": 100, "completion_tokens": 1}),
        Reply(content=json.dumps(GOOD), usage={"prompt_tokens": 110, "completion_tokens": 20}),
    )
    async with model_for(scripted_llm) as model:
        result = await structured_call(model, planning_request(), PlanOut)
    assert (result.usage.prompt_tokens, result.usage.completion_tokens) == (210, 21)
    assert result.latency_s == pytest.approx(sum(a.response.latency_s for a in result.attempts))


async def test_transport_failure_propagates_without_output_retries(
    scripted_llm: ScriptedLLM,
) -> None:
    scripted_llm.script("planning", server_error(), server_error(), json_reply(GOOD))
    async with model_for(scripted_llm) as model:
        with pytest.raises(LLMError):
            await structured_call(model, planning_request(), PlanOut, max_retries=5)
    assert len(scripted_llm.requests) == 2


async def test_handler_computes_answers_from_the_request(scripted_llm: ScriptedLLM) -> None:
    def answer(request: RecordedRequest) -> dict[str, object]:
        # Echo who the user asked about, so the answer depends on the prompt.
        person = "zhang" if "Zhang" in request.last_user_text else "lee"
        return {**GOOD, "contact": person}

    scripted_llm.respond_with(answer, agent="planning")
    request = planning_request().model_copy(
        update={"messages": (Message(role="user", content="Ask Zhang."),)}
    )
    async with model_for(scripted_llm) as model:
        result = await structured_call(model, request, PlanOut, grounded)
    assert result.output.contact == "zhang"


async def test_negative_retries_rejected(scripted_llm: ScriptedLLM) -> None:
    async with model_for(scripted_llm) as model:
        with pytest.raises(ValueError, match="max_retries"):
            await structured_call(model, planning_request(), PlanOut, max_retries=-1)
