"""Typed output from a chat model: parse, validate, feed the error back, retry.

``structured_call`` asks for JSON matching a pydantic model (its grammar-safe schema goes
with the request, so servers that enforce schemas do), pulls the JSON object out of whatever
the model wrote, validates it with pydantic and then with the caller's own check (grounding
names against memory, say). An answer cut at ``max_tokens`` (``finish_reason: length``) is
rejected whole, never parsed as a partial answer. Each of these steps says "the model's answer
is unusable" by raising :class:`~assistantx.core.errors.ModelOutputError`, and only that error
is fed back: anything else the caller's check raises (a KeyError, a TypeError, a plain
ValueError) is a bug of ours and propagates at once, never shown to the model as its fault.
When an answer is unusable the model tries again, up to ``max_retries`` times, on the
ORIGINAL conversation plus one user message with the error and a short excerpt of the
rejected answer: repairs never pile up, and a runaway answer is not echoed back into the next
prompt. Then ``ModelBehaviorError`` carries the last
error and every attempt.

Transport failures (``LLMError``) are not output problems and propagate at once; an
``LLMCallFailed`` gets the attempts made before it attached, so their cost is counted.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass
from typing import Generic, TypeVar

from pydantic import BaseModel, ValidationError

from assistantx.core.errors import ModelBehaviorError, ModelOutputError
from assistantx.core.ports.model import (
    ChatModel,
    ChatRequest,
    ChatResponse,
    LLMCallFailed,
    Message,
    Usage,
)
from assistantx.core.structured._json_extract import extract_json_object
from assistantx.core.structured.schema import grammar_schema

logger = logging.getLogger(__name__)

OutputT = TypeVar("OutputT", bound=BaseModel)

_MAX_INPUT_REPR = 80
_MAX_ECHO_CHARS = 240


@dataclass(frozen=True)
class Attempt:
    """One try: what the model said and, if it was rejected, why."""

    response: ChatResponse
    error: str | None

    @property
    def text(self) -> str:
        return self.response.text


@dataclass(frozen=True)
class StructuredResult(Generic[OutputT]):
    output: OutputT
    attempts: tuple[Attempt, ...]

    @property
    def usage(self) -> Usage:
        total = Usage()
        for attempt in self.attempts:
            total = total + attempt.response.usage
        return total

    @property
    def latency_s(self) -> float:
        return sum(a.response.latency_s for a in self.attempts)

    @property
    def repairs(self) -> int:
        """How many times invalid output had to be fed back."""
        return len(self.attempts) - 1


def describe_validation_error(error: ValidationError) -> str:
    """Pydantic's errors as short ``field: problem`` lines a model can act on."""
    lines = []
    for item in error.errors(include_url=False):
        where = ".".join(str(part) for part in item["loc"]) or "(the object)"
        line = f"{where}: {item['msg']}"
        value = item.get("input")
        if isinstance(value, (str, int, float, bool)) and item["type"] != "missing":
            shown = repr(value)
            if len(shown) > _MAX_INPUT_REPR:
                shown = shown[:_MAX_INPUT_REPR] + "…"
            line += f" (got {shown})"
        lines.append(line)
    return "; ".join(lines)


def feedback_message(error: str, answer: str = "") -> Message:
    """The repair request: the error, and at most a short excerpt of the rejected answer."""
    excerpt = answer.strip().replace("\n", " ")
    if len(excerpt) > _MAX_ECHO_CHARS:
        excerpt = excerpt[:_MAX_ECHO_CHARS] + "…"
    shown = f"Your previous answer began: {excerpt}\n" if excerpt else ""
    return Message(
        role="user",
        content=(
            f"{shown}It could not be used: {error}\n"
            "Answer again with only the corrected JSON object, no prose and no code fences."
        ),
    )


def cut_off_error(response: ChatResponse) -> str | None:
    """Why an answer stopped at the token limit cannot be used, or None when it did not."""
    if response.finish_reason != "length":
        return None
    return (
        f"the answer was cut off at the length limit ({response.usage.completion_tokens} "
        "tokens); give a much shorter JSON object"
    )


def _reject_cut_off(response: ChatResponse) -> None:
    cut = cut_off_error(response)
    if cut is not None:
        raise ModelOutputError(cut)


def parse_output(
    text: str,
    output_type: type[OutputT],
    validate: Callable[[OutputT], None] | None = None,
) -> OutputT:
    """Extract, validate and check one answer; ``ModelOutputError`` says why it is unusable.

    ``validate`` raises ``ModelOutputError`` for a problem of the answer; whatever else it
    raises is passed on untouched."""
    raw = extract_json_object(text)
    try:
        output = output_type.model_validate(raw)
    except ValidationError as exc:
        raise ModelOutputError(describe_validation_error(exc)) from exc
    if validate is not None:
        validate(output)
    return output


async def structured_call(
    model: ChatModel,
    request: ChatRequest,
    output_type: type[OutputT],
    validate: Callable[[OutputT], None] | None = None,
    max_retries: int = 2,
) -> StructuredResult[OutputT]:
    """Ask until the answer parses into ``output_type`` and passes ``validate``.

    ``validate`` signals a problem of the answer (a name memory does not know, say) by raising
    ``ModelOutputError``, whose text is fed back to the model; any other exception propagates.
    """
    if max_retries < 0:
        raise ValueError("max_retries must be >= 0")
    if request.json_schema is None:
        request = request.model_copy(
            update={
                "json_schema": grammar_schema(output_type),
                "schema_name": request.schema_name or output_type.__name__,
            }
        )
    original = request
    attempts: list[Attempt] = []
    for attempt_index in range(max_retries + 1):
        try:
            response = await model.complete(request)
        except LLMCallFailed as exc:
            exc.attempts = tuple(attempts)
            raise
        try:
            _reject_cut_off(response)
            output = parse_output(response.text, output_type, validate)
        except ModelOutputError as exc:
            error = str(exc) or type(exc).__name__
        else:
            attempts.append(Attempt(response=response, error=None))
            return StructuredResult(output=output, attempts=tuple(attempts))
        attempts.append(Attempt(response=response, error=error))
        logger.info(
            "%s output rejected (attempt %d of %d): %s",
            request.agent,
            attempt_index + 1,
            max_retries + 1,
            error,
        )
        request = original.followed_by(feedback_message(error, response.text)).model_copy(
            update={"attempt": attempt_index + 1}
        )
    raise ModelBehaviorError(
        f"{request.agent}: no valid {output_type.__name__} after {len(attempts)} attempt(s); "
        f"last error: {attempts[-1].error}",
        last_error=attempts[-1].error or "",
        attempts=attempts,
    )
