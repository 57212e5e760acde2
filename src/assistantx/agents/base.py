"""The four agents' interface. A reasoner (LLM, embedded symbolic, a baseline) implements it.

Each agent gets an ``AgentContext``: the memory (long- and short-term), the resolver for
grounding, the previous reflection and the feedback from the last step (refused actions,
grounding errors), and returns a pydantic output plus the accounting of its calls.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable
from dataclasses import dataclass, field

from assistantx.core.trace import (
    ActionResult,
    AgentCall,
    Decision,
    Observation,
    Percept,
    Plan,
    Reflection,
)
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory


@dataclass
class AgentContext:
    ltm: LongTermMemory
    stm: ShortTermMemory
    resolver: Resolver
    step: int
    now: float
    feedback: list[str] = field(default_factory=list)
    last_reflection: Reflection | None = None
    calls: list[AgentCall] = field(default_factory=list)

    def record(self, call: AgentCall) -> None:
        self.calls.append(call)


class Reasoner(ABC):
    """Perception, Planning, Decision and Reflection behind one object."""

    name: str = "abstract"

    async def start(self) -> None:  # noqa: B027 - optional hook
        """Open connections (an LLM client); idempotent."""

    async def stop(self) -> None:  # noqa: B027 - optional hook
        """Close connections; idempotent."""

    @abstractmethod
    async def perceive(self, ctx: AgentContext) -> Percept: ...

    @abstractmethod
    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan: ...

    @abstractmethod
    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        """Actions whose names must ground in memory; the loop grounds and may refuse them."""

    @abstractmethod
    async def reflect(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection: ...


ReasonerFactory = Callable[[], Reasoner]
"""Makes one reasoner per instruction (the registry builds them by name)."""
