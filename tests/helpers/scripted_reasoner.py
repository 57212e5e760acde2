"""The tests' stand-in for a reasoner: it plays back a script of decisions.

Each step is a list of actions, or a function of the agent context that returns one (to
decide from memory); an exhausted script waits. Reflection says Y when every action
succeeded, with the memory updates ``updates`` derives from the results. A subclass that
decides by a policy instead overrides ``next_actions``.
"""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.base import AgentContext, Reasoner
from assistantx.core.actions import Action, Wait
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
Updates = Callable[[AgentContext, list[ActionResult]], list[MemoryUpdate]]


class ScriptedReasoner(Reasoner):
    name = "scripted"

    def __init__(self, steps: list[Step], updates: Updates | None = None) -> None:
        self.steps = list(steps)
        self.updates = updates
        self.seen_feedback: list[list[str]] = []
        self.seen_reflections: list[Reflection | None] = []

    async def perceive(self, ctx: AgentContext) -> Percept:
        ctx.record(AgentCall(agent="perception"))
        return Percept(summary=self.name)

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        return Plan(goal=self.name, subgoals=[SubGoal(description="follow the script")])

    def next_actions(self, ctx: AgentContext) -> list[Action]:
        step = self.steps.pop(0) if self.steps else []
        return step(ctx) if callable(step) else step

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        self.seen_feedback.append(list(ctx.feedback))
        self.seen_reflections.append(ctx.last_reflection)
        actions = self.next_actions(ctx) or [Wait(reason="nothing to do", timeout_s=10)]
        return Decision(thought=self.name, actions=actions)

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
        return Reflection(verdict="Y" if ok else "N", reason=self.name, updates=updates)
