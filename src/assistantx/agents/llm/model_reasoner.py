"""A reasoner whose agents are structured calls to a shared chat model, accounted in the trace.

The base of the LLM reasoner and the paper's baselines. Each agent call is one
:func:`~assistantx.core.structured.structured_call`: the output is parsed, validated and
checked, and a failed check is fed back to the model up to ``output_retries`` times; then
:class:`~assistantx.core.errors.ModelBehaviorError` ends the instruction (the loop tells the
requester). One :class:`~assistantx.core.trace.AgentCall` per agent call (its repairs
included) goes to ``ctx.record``, so tokens and latency land in the trace, also when the call
gives up.

A reasoner that is used without ``start()`` starts itself on its first call (and then holds
the shared model until its ``stop()``).
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Awaitable, Callable, Sequence
from typing import TypeVar

from pydantic import BaseModel

from assistantx.agents.base import AgentContext, Reasoner
from assistantx.agents.llm.grounding import UNSURE_QUESTION, request_words, ungrounded_action
from assistantx.agents.llm.shared import ModelHold, SharedModel
from assistantx.core.actions import Inquire, Wait
from assistantx.core.errors import ModelBehaviorError, ModelOutputError
from assistantx.core.ports.model import ChatRequest, ChatResponse, LLMCallFailed, Message
from assistantx.core.structured import Attempt, structured_call
from assistantx.core.trace import AgentCall, Decision, Percept
from assistantx.memory.focus import (
    FocusBudget,
    focus_budget,
    merge_focus,
    render_focused,
    task_focus,
)

OutputT = TypeVar("OutputT", bound=BaseModel)
logger = logging.getLogger(__name__)


class ModelReasoner(Reasoner):
    """A reasoner whose agents are structured calls to a shared chat model, accounted in the
    trace. Holds the shared model from ``start`` to ``stop`` (both idempotent)."""

    def __init__(
        self,
        shared: SharedModel,
        *,
        output_retries: int = 2,
        budget: FocusBudget | None = None,
    ) -> None:
        if output_retries < 0:
            raise ValueError("output_retries must be >= 0")
        self.shared = shared
        self.output_retries = output_retries
        self.budget = budget or focus_budget(8192, 1024)
        self._hold = ModelHold(shared)

    def memory(self, ctx: AgentContext, percept: Percept | None = None) -> str:
        """The memory an agent sees: the task's focus (merged with the model's percept),
        capped to fit the context; never the whole office."""
        focus = merge_focus(percept, task_focus(ctx.ltm, ctx.stm))
        return render_focused(ctx.ltm, ctx.stm, focus, self.budget)

    async def start(self) -> None:
        await self._hold.take()

    async def stop(self) -> None:
        await self._hold.give_back()

    async def _grounded_decision(
        self,
        ctx: AgentContext,
        ask: Callable[[Callable[[Decision], None]], Awaitable[Decision]],
        check: Callable[[Decision], None],
    ) -> Decision:
        """A decision whose every action hands over only what the requester asked for.

        ``ask`` makes the structured call with the check it is given: ``check`` (the action
        checks) and then the grounding in the requester's words, fed back to the model like
        any check. When the model keeps proposing what was never asked for, its reading is
        not acted on: the requester is asked instead."""
        words = request_words(ctx.resolver.office, ctx.stm)
        refused: list[str] = []

        def grounded(decision: Decision) -> None:
            refused.clear()
            check(decision)
            for action in decision.actions:
                missing = ungrounded_action(words, ctx.stm.requester, ctx.resolver.ground(action))
                if missing is not None:
                    refused.append(missing)
                    raise ModelOutputError(
                        f"{action.type}: {missing}. Do only what the request says; when it "
                        "is unclear, inquire of the requester."
                    )

        try:
            return await ask(grounded)
        except ModelBehaviorError:
            if not refused:
                raise
            logger.info("decision not grounded in the request (%s): asking", refused[-1])
            return Decision(
                thought="the proposed actions are not what the requester asked for",
                actions=[
                    Inquire(contact=ctx.stm.requester, question=UNSURE_QUESTION),
                    Wait(reason="waiting for the requester to clarify"),
                ],
            )

    async def _ask(
        self,
        ctx: AgentContext,
        agent: str,
        messages: list[Message],
        output_type: type[OutputT],
        check: Callable[[OutputT], None] | None,
        *,
        schema_name: str | None = None,
    ) -> OutputT:
        """One structured call, its attempts recorded on ``ctx`` even when it gives up."""
        await self.start()
        request = ChatRequest(
            messages=tuple(messages),
            agent=agent,
            schema_name=schema_name,
            instruction_id=ctx.stm.instruction_id,
            step=ctx.step,
        )
        try:
            result = await structured_call(
                self.shared.model, request, output_type, check, max_retries=self.output_retries
            )
        except ModelBehaviorError as exc:
            attempts = [a for a in exc.attempts if isinstance(a, Attempt)]
            if attempts:
                ctx.record(agent_call(agent, attempts))
            raise
        except LLMCallFailed as exc:
            ctx.record(failed_call(agent, exc))
            raise
        except asyncio.CancelledError:
            ctx.record(interrupted_call(agent))
            raise
        ctx.record(agent_call(agent, result.attempts))
        return result.output


def interrupted_call(agent: str) -> AgentCall:
    """A call cut off by the instruction's own time limit: a request was in flight, what it
    cost is unknown (0 tokens, marked as an estimate)."""
    return AgentCall(agent=agent, attempts=1, estimated=True)


def failed_call(agent: str, exc: LLMCallFailed) -> AgentCall:
    """The accounting of a call that got no usable answer: its earlier (rejected) attempts,
    and the failed one with every request it sent and what they cost (estimated)."""
    earlier = [a for a in exc.attempts if isinstance(a, Attempt)]
    failed = Attempt(
        response=ChatResponse(
            text="",
            usage=exc.usage,
            latency_s=exc.latency_s,
            model=exc.model,
            retries=exc.retries,
        ),
        error=str(exc),
    )
    return agent_call(agent, [*earlier, failed])


def agent_call(agent: str, attempts: Sequence[Attempt]) -> AgentCall:
    """The trace's accounting of one agent call: every attempt's tokens and latency summed."""
    return AgentCall(
        agent=agent,
        model=attempts[-1].response.model if attempts else None,
        prompt_tokens=sum(a.response.usage.prompt_tokens for a in attempts),
        completion_tokens=sum(a.response.usage.completion_tokens for a in attempts),
        latency_s=sum(a.response.latency_s for a in attempts),
        # every request the server saw: repairs and transport retries included
        attempts=sum(1 + a.response.retries for a in attempts),
        estimated=any(a.response.usage.estimated for a in attempts),
    )
