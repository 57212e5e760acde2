"""The OpenAI-compatible client against the scripted server, over real HTTP on 127.0.0.1."""

from __future__ import annotations

import logging
import time
from typing import Any

import httpx
import pytest
from pydantic import SecretStr

from assistantx.adapters.model import ChatRequest, Message, OpenAICompatibleModel, RetryPolicy
from assistantx.core.errors import LLMError
from assistantx.core.ports.model import LLMCallFailed
from assistantx.core.settings import Settings
from fakes.scripted_llm import (
    Reply,
    ScriptedLLM,
    json_reply,
    rate_limited,
    reject_response_format,
    server_error,
    slow,
)
from helpers.servers import refusing_port

SCHEMA = {
    "type": "object",
    "properties": {"answer": {"type": "string"}},
    "required": ["answer"],
}


def tiny_retries(max_retries: int = 3, *, cap_s: float = 0.05) -> RetryPolicy:
    return RetryPolicy(
        max_retries=max_retries, base_delay_s=0.001, max_delay_s=0.005, retry_after_cap_s=cap_s
    )


def make_model(
    server: ScriptedLLM, *, retry: RetryPolicy | None = None, **kwargs: Any
) -> OpenAICompatibleModel:
    return OpenAICompatibleModel(
        server.base_url,
        "test-model",
        retry=retry or tiny_retries(),
        **kwargs,
    )


def ask(agent: str = "planning", text: str = "What next?", **kwargs: Any) -> ChatRequest:
    return ChatRequest(
        messages=(
            Message(role="system", content=f"AGENT: {agent}"),
            Message(role="user", content=text),
        ),
        agent=agent,
        **kwargs,
    )


async def test_answer_with_reported_usage(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script(
        "planning",
        Reply(content="go to the printer", usage={"prompt_tokens": 42, "completion_tokens": 7}),
    )
    async with make_model(scripted_llm) as model:
        response = await model.complete(ask())
    assert response.text == "go to the printer"
    assert (response.usage.prompt_tokens, response.usage.completion_tokens) == (42, 7)
    assert not response.usage.estimated
    assert response.finish_reason == "stop"
    assert response.model == "test-model"
    assert response.retries == 0
    assert response.latency_s > 0
    sent = scripted_llm.requests[0]
    assert sent.path == "/v1/chat/completions"
    assert sent.body["model"] == "test-model"
    assert sent.body["temperature"] == 0.0
    assert sent.body["seed"] == 0
    assert sent.body["stream"] is False
    assert "response_format" not in sent.body
    assert [m["role"] for m in sent.messages] == ["system", "user"]
    assert sent.agent == "planning"


async def test_missing_usage_is_estimated_from_text_length(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", Reply(content="x" * 40, usage=None))
    async with make_model(scripted_llm) as model:
        request = ask(text="y" * 100)
        response = await model.complete(request)
    prompt_chars = sum(len(m.content) for m in request.messages)
    assert response.usage.estimated
    assert response.usage.completion_tokens == 10
    assert response.usage.prompt_tokens == -(-prompt_chars // 4)


async def test_null_content_and_partial_usage_do_not_crash(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", Reply(content=None, usage={"prompt_tokens": 5}))
    async with make_model(scripted_llm) as model:
        response = await model.complete(ask())
    assert response.text == ""
    assert response.usage.prompt_tokens == 5
    assert response.usage.completion_tokens == 0
    assert response.usage.estimated


async def test_survives_a_429_storm_honouring_retry_after(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", *(rate_limited(0.1) for _ in range(3)), "finally")
    async with make_model(scripted_llm, retry=tiny_retries(cap_s=1.0)) as model:
        started = time.perf_counter()
        response = await model.complete(ask())
        elapsed = time.perf_counter() - started
    assert response.text == "finally"
    assert response.retries == 3
    assert len(scripted_llm.requests) == 4
    assert [r.status for r in scripted_llm.requests] == [429, 429, 429, 200]
    # Three waits of 0.1 s each, as the server asked, not the 1-5 ms backoff.
    assert elapsed >= 0.3


async def test_retry_after_is_capped(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", rate_limited(3600), rate_limited(3600), "ok")
    async with make_model(scripted_llm, retry=tiny_retries(cap_s=0.02)) as model:
        started = time.perf_counter()
        response = await model.complete(ask())
    assert response.text == "ok"
    assert time.perf_counter() - started < 2.0


async def test_server_error_then_success(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", server_error(500), server_error(503), "recovered")
    async with make_model(scripted_llm) as model:
        response = await model.complete(ask())
    assert response.text == "recovered"
    assert response.retries == 2


async def test_timeout_then_success(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", slow(5.0, "too late"), "in time")
    # a remote server's timeout is retried; the scripted one is local, so say it is wanted
    async with make_model(scripted_llm, timeout_s=0.2, retry_local_timeouts=True) as model:
        started = time.perf_counter()
        response = await model.complete(ask())
    assert response.text == "in time"
    assert response.retries == 1
    assert 0.2 <= time.perf_counter() - started < 2.0


async def test_retries_exhausted_raise_llm_error_with_cause(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", *(server_error(502, "bad gateway") for _ in range(3)), "unused")
    async with make_model(scripted_llm, retry=tiny_retries(max_retries=2)) as model:
        with pytest.raises(LLMError, match=r"after 3 attempt\(s\).*HTTP 502") as caught:
            await model.complete(ask())
    assert isinstance(caught.value.__cause__, httpx.HTTPStatusError)
    assert caught.value.__cause__.response.status_code == 502
    assert len(scripted_llm.requests) == 3
    assert scripted_llm.pending("planning") == 1


async def test_client_errors_are_not_retried(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", Reply(status=404, error="model 'test-model' not found"))
    async with make_model(scripted_llm) as model:
        with pytest.raises(LLMError, match=r"HTTP 404.*not found"):
            await model.complete(ask())
    assert len(scripted_llm.requests) == 1


async def test_connection_refused_is_retried_then_reported() -> None:
    with refusing_port() as port:
        url = f"http://127.0.0.1:{port}/v1"
        model = OpenAICompatibleModel(url, "m", retry=tiny_retries(max_retries=2))
        async with model:
            with pytest.raises(LLMError, match="connection failed") as caught:
                await model.complete(ask())
    assert isinstance(caught.value.__cause__, httpx.ConnectError)


async def test_body_that_is_not_json_is_a_clear_error(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", Reply(raw_body="<html>proxy says hi</html>"))
    async with make_model(scripted_llm) as model:
        with pytest.raises(LLMError, match=r"not JSON.*proxy says hi"):
            await model.complete(ask())


async def test_json_schema_response_format_is_sent(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("decision", json_reply({"answer": "a"}))
    async with make_model(scripted_llm) as model:
        response = await model.complete(ask("decision", json_schema=SCHEMA, schema_name="Decision"))
    assert response.structured_mode == "json_schema"
    assert scripted_llm.requests[0].response_format == {
        "type": "json_schema",
        "json_schema": {"name": "Decision", "schema": SCHEMA, "strict": False},
    }


async def test_response_format_falls_back_once_and_remembers(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.supports_json_schema = False  # like an older llama.cpp or vLLM
    scripted_llm.script("decision", json_reply({"answer": "a"}), json_reply({"answer": "b"}))
    async with make_model(scripted_llm) as model:
        first = await model.complete(ask("decision", json_schema=SCHEMA))
        second = await model.complete(ask("decision", json_schema=SCHEMA))
    assert (first.text, second.text) == ('{"answer": "a"}', '{"answer": "b"}')
    # llama.cpp's form: json_object with the schema in response_format, enforced there
    assert first.structured_mode == second.structured_mode == "json_object_schema"
    kinds = [(r.status, (r.response_format or {}).get("type")) for r in scripted_llm.requests]
    # The refusal happened once; the second call went straight to json_object.
    assert kinds == [(400, "json_schema"), (200, "json_object"), (200, "json_object")]
    assert scripted_llm.requests[1].response_format == {"type": "json_object", "schema": SCHEMA}
    # The server enforces the schema, so it is not pasted into the prompt as well.
    assert '"answer"' not in scripted_llm.requests[1].system_text


async def test_falls_back_to_plain_prompting(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.supports_json_schema = False
    scripted_llm.supports_json_object = False
    scripted_llm.script("decision", json_reply({"answer": "a"}))
    async with make_model(scripted_llm) as model:
        response = await model.complete(ask("decision", json_schema=SCHEMA))
        assert model.structured_mode == "prompt"
    assert response.structured_mode == "prompt"
    last = scripted_llm.requests[-1]
    assert last.response_format is None
    assert last.system_text.startswith("AGENT: decision\n\nAnswer with exactly one JSON object")
    # json_schema, json_object+schema, bare json_object (refused), then the prompt alone
    assert len(scripted_llm.requests) == 4


async def test_scripted_refusal_with_500_mentioning_response_format(
    scripted_llm: ScriptedLLM,
) -> None:
    scripted_llm.script("decision", reject_response_format(500), json_reply({"answer": "a"}))
    async with make_model(scripted_llm) as model:
        response = await model.complete(ask("decision", json_schema=SCHEMA))
    assert response.structured_mode == "json_object_schema"
    # not retried as a 500: refused once, then the fallback; both requests count
    assert len(scripted_llm.requests) == 2
    assert response.retries == 1


async def test_a_400_about_something_else_does_not_fall_back(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("decision", Reply(status=400, error="messages: too long for context"))
    async with make_model(scripted_llm) as model:
        with pytest.raises(LLMError, match="too long"):
            await model.complete(ask("decision", json_schema=SCHEMA))
        assert model.structured_mode == "json_schema"


async def test_api_key_sent_as_bearer_and_never_logged(
    scripted_llm: ScriptedLLM, caplog: pytest.LogCaptureFixture
) -> None:
    secret = "sk-test-very-secret-4242"
    scripted_llm.api_key = secret
    scripted_llm.script("planning", server_error(500), "authorized")
    caplog.set_level(logging.DEBUG)
    model = make_model(scripted_llm, api_key=SecretStr(secret))
    async with model:
        response = await model.complete(ask(text="prompt body here"))
    assert response.text == "authorized"
    assert scripted_llm.requests[-1].headers["authorization"] == f"Bearer {secret}"
    assert secret not in caplog.text
    assert secret not in repr(model)
    # Bodies are logged at DEBUG (the key is not in them) and the retry at WARNING.
    assert "prompt body here" in caplog.text
    assert any(
        r.levelno == logging.WARNING and "retry 1 of 3" in r.getMessage() for r in caplog.records
    )


async def test_wrong_key_is_an_error_without_the_key(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.api_key = "right"
    scripted_llm.script("planning", "unused")
    async with make_model(scripted_llm, api_key="wrong-key-123") as model:
        with pytest.raises(LLMError, match="HTTP 401") as caught:
            await model.complete(ask())
    assert "wrong-key-123" not in str(caught.value)


async def test_no_key_sends_no_authorization_header(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", "fine")
    async with make_model(scripted_llm) as model:
        await model.complete(ask())
    assert "authorization" not in scripted_llm.requests[0].headers


async def test_bodies_are_not_logged_when_disabled(
    scripted_llm: ScriptedLLM, caplog: pytest.LogCaptureFixture
) -> None:
    scripted_llm.script("planning", "the completion text")
    caplog.set_level(logging.DEBUG)
    async with make_model(scripted_llm, log_bodies=False) as model:
        await model.complete(ask(text="the prompt text"))
    assert "the prompt text" not in caplog.text
    assert "the completion text" not in caplog.text


async def test_complete_requires_start(scripted_llm: ScriptedLLM) -> None:
    model = make_model(scripted_llm)
    with pytest.raises(RuntimeError, match="not started"):
        await model.complete(ask())


async def test_start_and_stop_are_idempotent(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", "one", "two")
    model = make_model(scripted_llm)
    await model.start()
    await model.start()
    assert (await model.complete(ask())).text == "one"
    await model.stop()
    await model.stop()
    assert not model.started
    async with model:  # a stopped model can start again
        assert (await model.complete(ask())).text == "two"


def test_from_settings_takes_the_llm_fields() -> None:
    settings = Settings(
        llm_base_url="http://127.0.0.1:9/v1/",
        llm_model="qwen",
        llm_api_key=SecretStr("k"),
        llm_timeout_s=5.0,
        llm_temperature=0.3,
        llm_seed=7,
        llm_max_retries=1,
    )
    model = OpenAICompatibleModel.from_settings(settings)
    assert model.endpoint == "http://127.0.0.1:9/v1/chat/completions"
    assert (model.model, model.timeout_s, model.temperature, model.seed) == ("qwen", 5.0, 0.3, 7)
    assert model.retry.max_retries == 1
    with pytest.raises(ValueError, match="ASSISTANTX_LLM_BASE_URL"):
        OpenAICompatibleModel.from_settings(Settings(llm_base_url=None))


def test_bad_base_url_is_rejected() -> None:
    with pytest.raises(ValueError, match="http"):
        OpenAICompatibleModel("localhost:11434/v1", "m")


async def test_a_timeout_against_a_local_server_is_not_retried(scripted_llm: ScriptedLLM) -> None:
    # The local server is still generating for the call that gave up; a retry would queue
    # behind that abandoned generation.
    scripted_llm.script("planning", slow(5.0, "too late"), "never asked")
    async with make_model(scripted_llm, timeout_s=0.2) as model:
        with pytest.raises(LLMCallFailed, match="after 1 attempt") as caught:
            await model.complete(ask(text="word " * 400))
    assert len(scripted_llm.requests) == 1
    error = caught.value
    assert error.user_text == "my language model server took too long to answer"
    assert "http" not in error.user_text
    # what the failed call cost is counted: the prompt was sent and read
    assert error.usage.prompt_tokens >= 400
    assert error.usage.estimated
    assert error.latency_s >= 0.2


async def test_call_budget_bounds_a_call_that_keeps_the_connection_busy(
    scripted_llm: ScriptedLLM,
) -> None:
    scripted_llm.script("planning", slow(5.0, "too late"))
    async with make_model(scripted_llm, timeout_s=30.0, call_budget_s=0.3) as model:
        started = time.perf_counter()
        with pytest.raises(LLMCallFailed, match="budget"):
            await model.complete(ask())
    assert time.perf_counter() - started < 2.0


async def test_a_fixed_structured_mode_never_falls_back(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.supports_json_schema = False
    async with make_model(scripted_llm, structured="json_schema") as model:
        with pytest.raises(LLMCallFailed, match="ASSISTANTX_LLM_STRUCTURED_OUTPUT"):
            await model.complete(ask("decision", json_schema=SCHEMA))
    assert len(scripted_llm.requests) == 1


async def test_max_tokens_is_sent(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("planning", "ok")
    async with make_model(scripted_llm, max_tokens=321) as model:
        await model.complete(ask())
    assert scripted_llm.requests[0].body["max_tokens"] == 321


async def test_a_streamed_request_answered_with_plain_json_is_read(
    scripted_llm: ScriptedLLM,
) -> None:
    scripted_llm.script("planning", Reply(content="plain", finish_reason="length"))
    async with make_model(scripted_llm, stream=True) as model:
        response = await model.complete(ask())
    assert scripted_llm.requests[0].body["stream"] is True
    assert (response.text, response.finish_reason) == ("plain", "length")
