"""Ablations of PPDR as Reasoner wrappers, so they apply to any reasoner (symbolic or LLM).

- ``NoPerception``: no focus step; Planning and Decision get an empty percept, which makes
  the memory renderer show the whole memory instead of the focus content.
- ``NoPlanning``: no hierarchical plan; Decision gets a one-line plan (the instruction).
- ``NoReflection``: no reflection; every step is judged "Y" and memory is never updated.
"""

from __future__ import annotations

from assistantx.agents.base import AgentContext, Reasoner
from assistantx.core.trace import (
    ActionResult,
    Decision,
    Observation,
    Percept,
    Plan,
    Reflection,
    SubGoal,
)


class _Wrapper(Reasoner):
    def __init__(self, inner: Reasoner) -> None:
        self.inner = inner
        self.name = f"{inner.name}-{self.suffix}"

    suffix = "wrapped"

    async def start(self) -> None:
        await self.inner.start()

    async def stop(self) -> None:
        await self.inner.stop()

    async def perceive(self, ctx: AgentContext) -> Percept:
        return await self.inner.perceive(ctx)

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        return await self.inner.plan(ctx, percept)

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        return await self.inner.decide(ctx, percept, plan)

    async def reflect(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection:
        return await self.inner.reflect(ctx, percept, plan, decision, results, observed)


class NoPerception(_Wrapper):
    suffix = "no-perception"

    async def perceive(self, ctx: AgentContext) -> Percept:
        return Percept(summary="")


class NoPlanning(_Wrapper):
    suffix = "no-planning"

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        return Plan(
            goal=ctx.stm.text[:1000] or "the instruction",
            subgoals=[SubGoal(description="carry out the instruction")],
        )


class NoReflection(_Wrapper):
    suffix = "no-reflection"

    async def reflect(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection:
        return Reflection(verdict="Y", reason="reflection is ablated")


ABLATIONS: dict[str, type[_Wrapper]] = {
    "ppdr-no-perception": NoPerception,
    "ppdr-no-planning": NoPlanning,
    "ppdr-no-reflection": NoReflection,
}
