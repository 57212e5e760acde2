"""Token and latency accounting for LLM calls.

A :class:`UsageLedger` records one :class:`CallRecord` per call to the model (every repair
attempt is its own call, and a call that failed is recorded with what it cost) and sums
them per agent, per step of an instruction and per instruction. It serializes to plain JSON
for the trace and the evaluator's report, and loads back. :class:`MeteredModel` wraps any
``ChatModel`` and records every call it forwards, so agents need not do the bookkeeping
themselves.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from assistantx.core.ports.model import ChatModel, ChatRequest, ChatResponse, LLMCallFailed


class CallRecord(BaseModel):
    """One model call as the ledger keeps it."""

    model_config = ConfigDict(frozen=True)

    agent: str
    instruction_id: str | None = None
    step: int | None = None
    model: str = ""
    prompt_tokens: int = Field(default=0, ge=0)
    completion_tokens: int = Field(default=0, ge=0)
    latency_s: float = Field(default=0.0, ge=0.0)
    retries: int = Field(default=0, ge=0, description="transport retries behind this call")
    attempt: int = Field(default=0, ge=0, description="0, or the n-th repair of bad output")
    estimated: bool = Field(default=False, description="token counts estimated, not reported")
    failed: bool = Field(default=False, description="no usable answer (timeout, error)")


class UsageTotals(BaseModel):
    """Sums over a set of calls."""

    calls: int = 0
    prompt_tokens: int = 0
    completion_tokens: int = 0
    total_tokens: int = 0
    latency_s: float = 0.0
    retries: int = 0
    repairs: int = Field(default=0, description="calls that were repair attempts")
    estimated_calls: int = 0

    @classmethod
    def of(cls, records: Iterable[CallRecord]) -> UsageTotals:
        totals = cls()
        for record in records:
            totals.calls += 1
            totals.prompt_tokens += record.prompt_tokens
            totals.completion_tokens += record.completion_tokens
            totals.latency_s += record.latency_s
            totals.retries += record.retries
            totals.repairs += 1 if record.attempt > 0 else 0
            totals.estimated_calls += 1 if record.estimated else 0
        totals.total_tokens = totals.prompt_tokens + totals.completion_tokens
        totals.latency_s = round(totals.latency_s, 6)
        return totals


class UsageLedger:
    """An append-only list of calls with totals by agent, step and instruction."""

    def __init__(self, records: Iterable[CallRecord] = ()) -> None:
        self._records: list[CallRecord] = list(records)

    def __len__(self) -> int:
        return len(self._records)

    @property
    def records(self) -> tuple[CallRecord, ...]:
        return tuple(self._records)

    def record(self, request: ChatRequest, response: ChatResponse) -> CallRecord:
        """Add the call that answered ``request`` with ``response``."""
        return self._add(request, response, failed=False)

    def record_failure(self, request: ChatRequest, error: LLMCallFailed) -> CallRecord:
        """Add a call that failed, with what it cost before it did."""
        return self._add(request, error, failed=True)

    def _add(
        self, request: ChatRequest, outcome: ChatResponse | LLMCallFailed, *, failed: bool
    ) -> CallRecord:
        # An answer and a failure carry the same cost fields: one record shape for both.
        entry = CallRecord(
            agent=request.agent,
            instruction_id=request.instruction_id,
            step=request.step,
            model=outcome.model,
            prompt_tokens=outcome.usage.prompt_tokens,
            completion_tokens=outcome.usage.completion_tokens,
            latency_s=outcome.latency_s,
            retries=outcome.retries,
            attempt=request.attempt,
            estimated=outcome.usage.estimated,
            failed=failed,
        )
        self._records.append(entry)
        return entry

    def add(self, entry: CallRecord) -> None:
        self._records.append(entry)

    def select(
        self,
        *,
        agent: str | None = None,
        instruction_id: str | None = None,
        step: int | None = None,
    ) -> list[CallRecord]:
        return [
            r
            for r in self._records
            if (agent is None or r.agent == agent)
            and (instruction_id is None or r.instruction_id == instruction_id)
            and (step is None or r.step == step)
        ]

    def totals(
        self,
        *,
        agent: str | None = None,
        instruction_id: str | None = None,
        step: int | None = None,
    ) -> UsageTotals:
        return UsageTotals.of(self.select(agent=agent, instruction_id=instruction_id, step=step))

    def by_agent(self, instruction_id: str | None = None) -> dict[str, UsageTotals]:
        return self._group(lambda r: r.agent, self.select(instruction_id=instruction_id))

    def by_instruction(self) -> dict[str, UsageTotals]:
        """Totals per instruction; calls made outside any instruction are left out."""
        return self._group(
            lambda r: r.instruction_id, [r for r in self._records if r.instruction_id]
        )

    def by_step(self, instruction_id: str) -> dict[int, UsageTotals]:
        """Totals per step of one instruction; calls without a step are left out."""
        grouped = self._group(
            lambda r: r.step,
            [r for r in self.select(instruction_id=instruction_id) if r.step is not None],
        )
        return dict(sorted(grouped.items()))

    @staticmethod
    def _group(key: Callable[[CallRecord], Any], records: list[CallRecord]) -> dict[Any, Any]:
        groups: dict[Any, list[CallRecord]] = {}
        for record in records:
            groups.setdefault(key(record), []).append(record)
        return {k: UsageTotals.of(v) for k, v in groups.items()}

    def to_dict(self) -> dict[str, Any]:
        """The ledger as plain JSON-able data: totals, breakdowns and every call."""
        instructions = {
            instruction: {
                "totals": totals.model_dump(),
                "by_agent": {a: t.model_dump() for a, t in self.by_agent(instruction).items()},
                "by_step": {str(s): t.model_dump() for s, t in self.by_step(instruction).items()},
            }
            for instruction, totals in self.by_instruction().items()
        }
        return {
            "totals": self.totals().model_dump(),
            "by_agent": {a: t.model_dump() for a, t in self.by_agent().items()},
            "by_instruction": instructions,
            "calls": [r.model_dump() for r in self._records],
        }

    def to_json(self, **dumps_kwargs: Any) -> str:
        return json.dumps(self.to_dict(), **dumps_kwargs)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> UsageLedger:
        """Rebuild from :meth:`to_dict` output; only ``calls`` is read, totals are derived."""
        calls = data.get("calls")
        if not isinstance(calls, list):
            raise TypeError("usage ledger data needs a 'calls' list")
        return cls(CallRecord.model_validate(c) for c in calls)


class MeteredModel(ChatModel):
    """A ``ChatModel`` that forwards to another and records every answered call.

    Starting and stopping the wrapper starts and stops the wrapped model.
    """

    def __init__(self, inner: ChatModel, ledger: UsageLedger) -> None:
        super().__init__()
        self.inner = inner
        self.ledger = ledger

    async def _start(self) -> None:
        await self.inner.start()

    async def _stop(self) -> None:
        await self.inner.stop()

    async def _complete(self, request: ChatRequest) -> ChatResponse:
        try:
            response = await self.inner.complete(request)
        except LLMCallFailed as exc:
            self.ledger.record_failure(request, exc)
            raise
        self.ledger.record(request, response)
        return response
