"""A reasoner that plays back a script of decisions: for testing the loop's mechanics."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.base import AgentContext, Reasoner
from assistantx.core.actions import Action
from assistantx.core.trace import (
    ActionResult,
    AgentCall,
    Decision,
    Observation,
    Percept,
    Plan,
    Reflection,
    SubGoal,
)
from assistantx.memory.updates import MemoryUpdate

Step = list[Action] | Callable[[AgentContext], list[Action]]


class ScriptedReasoner(Reasoner):
    name = "scripted"

    def __init__(
        self,
        steps: list[Step],
        updates: Callable[[AgentContext, list[ActionResult]], list[MemoryUpdate]] | None = None,
    ) -> None:
        self.steps = list(steps)
        self.updates = updates
        self.seen_feedback: list[list[str]] = []
        self.seen_reflections: list[Reflection | None] = []

    async def perceive(self, ctx: AgentContext) -> Percept:
        ctx.record(AgentCall(agent="perception"))
        return Percept(summary="scripted")

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        return Plan(goal="scripted", subgoals=[SubGoal(description="follow the script")])

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        self.seen_feedback.append(list(ctx.feedback))
        self.seen_reflections.append(ctx.last_reflection)
        step = self.steps.pop(0) if self.steps else []
        actions = step(ctx) if callable(step) else step
        if not actions:
            from assistantx.core.actions import Wait

            actions = [Wait(reason="nothing to do", timeout_s=10)]
        return Decision(thought="scripted", actions=actions)

    async def reflect(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection:
        ok = all(r.ok for r in results)
        updates = self.updates(ctx, results) if self.updates else []
        return Reflection(verdict="Y" if ok else "N", reason="scripted", updates=updates)
