"""Every request a call sends is counted, with what it cost, against a real local server.

A refused connection is a try that cost nothing; a try that timed out cost the prompt (an
estimate, marked so); an answer costs what the server reports, streamed or not. The figures
reach the trace through the reasoners' accounting (``failed_call`` / ``agent_call``).
"""

from __future__ import annotations

import asyncio
import json
from collections.abc import AsyncIterator

import pytest
from fastapi import FastAPI
from fastapi.responses import StreamingResponse
from pydantic import BaseModel

from assistantx.adapters.model import ChatRequest, Message, OpenAICompatibleModel, RetryPolicy
from assistantx.adapters.model._wire import estimate_tokens, prompt_estimate
from assistantx.agents.llm import agent_call, failed_call
from assistantx.core.ports.model import LLMCallFailed
from assistantx.core.structured import structured_call
from fakes.scripted_llm import Reply, ScriptedLLM, json_reply
from helpers.servers import refusing_port, serve_asgi

PROMPT = "Which of the two is closer to the printer?"


def ask() -> ChatRequest:
    return ChatRequest(messages=(Message(role="user", content=PROMPT),), agent="planning")


def quick(max_retries: int) -> RetryPolicy:
    return RetryPolicy(max_retries=max_retries, base_delay_s=0.001, max_delay_s=0.002)


def estimated_prompt() -> int:
    return prompt_estimate([{"role": "user", "content": PROMPT}])


async def test_refused_connections_are_tries_that_cost_nothing() -> None:
    with refusing_port() as port:
        url = f"http://127.0.0.1:{port}/v1"
        async with OpenAICompatibleModel(url, "m", retry=quick(3)) as model:
            with pytest.raises(LLMCallFailed) as caught:
                await model.complete(ask())
    failed = caught.value
    assert failed.retries == 3  # four requests tried
    assert (failed.usage.prompt_tokens, failed.usage.completion_tokens) == (0, 0)
    assert failed.user_text == "I could not reach my language model server"
    call = failed_call("planning", failed)
    assert (call.attempts, call.prompt_tokens, call.completion_tokens) == (4, 0, 0)


async def test_a_timed_out_try_costs_the_prompt_marked_as_an_estimate(
    scripted_llm: ScriptedLLM,
) -> None:
    scripted_llm.script(
        "planning", Reply(content="late", delay_s=30), Reply(content="late", delay_s=30)
    )
    async with OpenAICompatibleModel(
        scripted_llm.base_url, "m", timeout_s=0.3, retry=quick(1), retry_local_timeouts=True
    ) as model:
        with pytest.raises(LLMCallFailed) as caught:
            await model.complete(ask())
    failed = caught.value
    assert len(scripted_llm.requests) == 2 and failed.retries == 1
    assert failed.usage.prompt_tokens == 2 * estimated_prompt()
    assert failed.usage.estimated
    call = failed_call("planning", failed)
    assert call.attempts == 2 == len(scripted_llm.requests) and call.estimated


async def test_the_call_budget_ends_a_call_and_it_is_still_counted(
    scripted_llm: ScriptedLLM,
) -> None:
    scripted_llm.script("planning", Reply(content="late", delay_s=30))
    async with OpenAICompatibleModel(
        scripted_llm.base_url, "m", timeout_s=60, call_budget_s=0.3, retry=quick(2)
    ) as model:
        with pytest.raises(LLMCallFailed, match="budget") as caught:
            await model.complete(ask())
    assert caught.value.retries == 0 and len(scripted_llm.requests) == 1
    assert caught.value.usage.prompt_tokens == estimated_prompt()


@pytest.mark.parametrize("stream", [False, True])
async def test_the_servers_own_counts_are_used_streamed_or_not(
    scripted_llm: ScriptedLLM, stream: bool
) -> None:
    scripted_llm.streams = True
    usage = {"prompt_tokens": 37, "completion_tokens": 5, "total_tokens": 42}
    scripted_llm.script("planning", json_reply({"answer": "the first one"}, usage=usage))
    async with OpenAICompatibleModel(
        scripted_llm.base_url, "m", stream=stream, retry=quick(0)
    ) as model:
        response = await model.complete(ask())
    sent = scripted_llm.requests[0].body
    assert sent.get("stream_options") == ({"include_usage": True} if stream else None)
    assert json.loads(response.text) == {"answer": "the first one"}
    assert (response.usage.prompt_tokens, response.usage.completion_tokens) == (37, 5)
    assert not response.usage.estimated


async def test_without_server_counts_the_estimate_says_so(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.streams = True
    scripted_llm.script("planning", Reply(content="the first one", usage=None))
    async with OpenAICompatibleModel(
        scripted_llm.base_url, "m", stream=True, retry=quick(0)
    ) as model:
        response = await model.complete(ask())
    assert response.usage.estimated
    assert response.usage.completion_tokens == estimate_tokens("the first one")


class Answer(BaseModel):
    answer: str


async def test_repairs_and_server_retries_all_count(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script(
        "planning",
        Reply(status=503, error="busy"),
        Reply(content="not json"),
        json_reply({"answer": "ok"}),
    )
    async with OpenAICompatibleModel(scripted_llm.base_url, "m", retry=quick(2)) as model:
        result = await structured_call(model, ask(), Answer, max_retries=2)
    call = agent_call("planning", result.attempts)
    assert call.attempts == 3 == len(scripted_llm.requests)


async def test_a_streamed_answer_cut_off_midway_is_one_request() -> None:
    release = asyncio.Event()
    app = FastAPI()

    @app.post("/v1/chat/completions")
    async def stalls() -> StreamingResponse:
        async def body() -> AsyncIterator[str]:
            yield 'data: {"choices": [{"index": 0, "delta": {"content": "{\\"answer"}}]}\n\n'
            await release.wait()  # the rest never comes while the client waits

        return StreamingResponse(body(), media_type="text/event-stream")

    async with serve_asgi(app) as url:
        async with OpenAICompatibleModel(
            f"{url}/v1", "m", stream=True, call_budget_s=0.5, retry=quick(2)
        ) as model:
            with pytest.raises(LLMCallFailed) as caught:
                await model.complete(ask())
        release.set()
    failed = caught.value
    assert (failed.kind, failed.retries) == ("timed_out", 0)  # one request, not two
    assert failed.usage.prompt_tokens == estimated_prompt()
    assert failed.usage.completion_tokens == estimate_tokens('{"answer')
