"""The scripted server itself: agent recognition, queues, handlers, refusals, records."""

from __future__ import annotations

import asyncio
import time

import httpx
import pytest

from fakes.scripted_llm import RecordedRequest, Reply, ScriptedLLM, json_reply, rate_limited, slow


def chat(*messages: tuple[str, str], **extra: object) -> dict[str, object]:
    return {
        "model": "m",
        "messages": [{"role": r, "content": c} for r, c in messages],
        **extra,
    }


async def post(
    server: ScriptedLLM, body: object, headers: dict[str, str] | None = None
) -> httpx.Response:
    async with httpx.AsyncClient() as client:
        return await client.post(
            f"{server.base_url}/chat/completions", json=body, headers=headers or {}
        )


async def test_agent_from_header_prompt_line_or_schema_name(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", "from header")
    scripted_llm.script("reflection", "from prompt")
    scripted_llm.script("Decision", "from schema")
    by_header = await post(
        scripted_llm, chat(("user", "x")), headers={"X-AssistantX-Agent": "planning"}
    )
    by_prompt = await post(scripted_llm, chat(("system", "Hi.\nAGENT: reflection"), ("user", "x")))
    by_schema = await post(
        scripted_llm,
        chat(
            ("user", "x"),
            response_format={
                "type": "json_schema",
                "json_schema": {"name": "Decision", "schema": {}},
            },
        ),
    )
    texts = [
        r.json()["choices"][0]["message"]["content"] for r in (by_header, by_prompt, by_schema)
    ]
    assert texts == ["from header", "from prompt", "from schema"]
    assert [r.agent for r in scripted_llm.requests] == ["planning", "reflection", "Decision"]


async def test_wildcard_queue_then_handler_then_nothing(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("*", json_reply({"n": 1}))
    first = await post(scripted_llm, chat(("system", "AGENT: a"), ("user", "q")))
    assert first.json()["choices"][0]["message"]["content"] == '{"n": 1}'
    scripted_llm.respond_with(lambda req: f"echo {req.last_user_text}", agent="a")
    second = await post(scripted_llm, chat(("system", "AGENT: a"), ("user", "q2")))
    assert second.json()["choices"][0]["message"]["content"] == "echo q2"
    third = await post(scripted_llm, chat(("system", "AGENT: b"), ("user", "q3")))
    assert third.status_code == 400
    assert "nothing scripted for agent 'b'" in third.json()["error"]["message"]
    assert scripted_llm.unscripted == 1
    assert [r.status for r in scripted_llm.requests] == [200, 200, 400]


async def test_usage_auto_explicit_and_absent(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script(
        "*",
        Reply(content="two words"),
        Reply(content="x", usage={"prompt_tokens": 9, "completion_tokens": 1}),
        Reply(content="x", usage=None),
    )
    body = chat(("user", "three words here"))
    auto, explicit, absent = [(await post(scripted_llm, body)).json() for _ in range(3)]
    assert auto["usage"] == {"prompt_tokens": 3, "completion_tokens": 2, "total_tokens": 5}
    assert explicit["usage"] == {"prompt_tokens": 9, "completion_tokens": 1}
    assert "usage" not in absent


async def test_refusals_happen_before_the_script(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.supports_json_schema = False
    scripted_llm.api_key = "k"
    scripted_llm.script("*", "kept")
    unauthorized = await post(scripted_llm, chat(("user", "x")))
    assert unauthorized.status_code == 401
    refused = await post(
        scripted_llm,
        chat(("user", "x"), response_format={"type": "json_schema", "json_schema": {}}),
        headers={"Authorization": "Bearer k"},
    )
    assert refused.status_code == 400
    assert "response_format" in refused.json()["error"]["message"]
    assert scripted_llm.pending() == 1


async def test_body_that_is_not_an_object_is_rejected(scripted_llm: ScriptedLLM) -> None:
    response = await post(scripted_llm, [1, 2])
    assert response.status_code == 400
    assert scripted_llm.requests[0].status == 400


async def test_rate_limit_carries_retry_after(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("*", rate_limited(7))
    response = await post(scripted_llm, chat(("user", "x")))
    assert response.status_code == 429
    assert response.headers["retry-after"] == "7"
    assert response.json()["error"]["type"] == "rate_limit_error"


async def test_stop_wakes_slow_replies_and_frees_the_port() -> None:
    server = ScriptedLLM()
    await server.start()
    url = server.base_url
    arrived = asyncio.Event()

    def late_reply(_: RecordedRequest) -> Reply:
        arrived.set()
        return slow(30.0, "late")

    server.respond_with(late_reply)
    in_flight = asyncio.create_task(post(server, chat(("user", "x"))))
    await asyncio.wait_for(arrived.wait(), timeout=5)
    started = time.perf_counter()
    await server.stop()
    assert time.perf_counter() - started < 2.0  # not the 30 s the reply was scripted to take
    response = await in_flight
    assert response.json()["choices"][0]["message"]["content"] == "late"
    await server.stop()  # idempotent
    with pytest.raises(RuntimeError, match="not running"):
        _ = ScriptedLLM().base_url
    async with httpx.AsyncClient() as client:
        with pytest.raises(httpx.ConnectError):
            await client.get(f"{url}/models")
