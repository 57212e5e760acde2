"""structured_call feeds back ModelOutputError only; anything else its check raises is ours."""

from __future__ import annotations

import pytest
from pydantic import BaseModel

from assistantx.adapters.model import ChatRequest, Message, OpenAICompatibleModel, structured_call
from assistantx.core.errors import ModelOutputError
from fakes.scripted_llm import ScriptedLLM, json_reply


class Answer(BaseModel):
    contact: str


def request() -> ChatRequest:
    return ChatRequest(messages=(Message(role="user", content="Who?"),), agent="planning")


async def test_model_output_error_is_fed_back_and_retried(scripted_llm: ScriptedLLM) -> None:
    def known(answer: Answer) -> None:
        if answer.contact != "lee":
            raise ModelOutputError(f"no person named {answer.contact!r}; known: lee")

    scripted_llm.script("planning", json_reply({"contact": "wang"}), json_reply({"contact": "lee"}))
    async with OpenAICompatibleModel(scripted_llm.base_url, "m") as model:
        result = await structured_call(model, request(), Answer, known)
    assert result.output.contact == "lee" and result.repairs == 1
    assert "It could not be used: no person named 'wang'" in scripted_llm.requests[1].last_user_text


@pytest.mark.parametrize("error", [KeyError, TypeError, AttributeError, ValueError])
async def test_a_bug_in_the_check_propagates_after_one_request(
    error: type[Exception], scripted_llm: ScriptedLLM
) -> None:
    def buggy(answer: Answer) -> None:
        raise error("a bug in our check")

    scripted_llm.script("planning", json_reply({"contact": "lee"}), json_reply({"contact": "lee"}))
    async with OpenAICompatibleModel(scripted_llm.base_url, "m") as model:
        with pytest.raises(error, match="a bug in our check"):
            await structured_call(model, request(), Answer, buggy, max_retries=2)
    assert len(scripted_llm.requests) == 1


async def test_a_pydantic_error_inside_our_check_is_ours_too(scripted_llm: ScriptedLLM) -> None:
    """Only the answer's own validation against the output type is the model's fault."""

    def buggy(answer: Answer) -> None:
        Answer.model_validate({})  # our bug: builds a model from nothing

    scripted_llm.script("planning", json_reply({"contact": "lee"}))
    async with OpenAICompatibleModel(scripted_llm.base_url, "m") as model:
        with pytest.raises(ValueError, match="contact"):
            await structured_call(model, request(), Answer, buggy, max_retries=2)
    assert len(scripted_llm.requests) == 1
