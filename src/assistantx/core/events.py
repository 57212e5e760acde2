"""Trace events: what the loop tells the journal, the SSE stream and the dashboard as it runs."""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import Any, Literal

from pydantic import BaseModel

EventKind = Literal[
    "instruction_started",
    "step_started",
    "percept",
    "plan",
    "decision",
    "action_result",
    "observation",
    "reflection",
    "memory_updated",
    "feedback",
    "queued",
    "instruction_ended",
]


class TraceEvent(BaseModel):
    instruction_id: str
    kind: EventKind
    time: float
    step: int | None = None
    data: dict[str, Any] = {}


EventSink = Callable[[TraceEvent], Awaitable[None]]
