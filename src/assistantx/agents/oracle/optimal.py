"""The optimal policy as a Reasoner, so it runs through the same PPDR loop as every method.

It is given the task's spec (what the instruction means) but learns availability only from
what happens: who answered a wait, whether a hand-over succeeded. One decision is one batch
of the policy; perception, planning and reflection are bookkeeping and cost no model call.
"""

from __future__ import annotations

from assistantx.agents.base import AgentContext, Reasoner
from assistantx.agents.oracle.plan import build_plan
from assistantx.agents.oracle.policy import Feedback, PolicyLog, Script, optimal_script
from assistantx.core.errors import ReasonerError
from assistantx.core.office import Office
from assistantx.core.task_spec import BaseInstruction, Part
from assistantx.core.trace import (
    ActionResult,
    Decision,
    Observation,
    Percept,
    Plan,
    Reflection,
    SubGoal,
    all_ok,
)


class OptimalReasoner(Reasoner):
    name = "optimal"

    def __init__(self, office: Office, base: BaseInstruction) -> None:
        self.office = office
        self.base = base
        self.task_plan = build_plan(base, office)
        self.log = PolicyLog()
        self._script: Script | None = None
        self._done = False

    @classmethod
    def for_task(
        cls, office: Office, task_id: str, requester: str, text: str, spec: list[Part] | None
    ) -> OptimalReasoner:
        if not spec:
            raise ReasonerError(f"task {task_id} has no 'spec'; the optimal method needs one")
        base = BaseInstruction(id=task_id, requester=requester, text=text, parts=tuple(spec))
        return cls(office, base)

    async def perceive(self, ctx: AgentContext) -> Percept:
        return Percept(summary="the task spec is known; availability is found out by asking")

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        return Plan(goal=self.base.text, subgoals=[SubGoal(description="follow the policy")])

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        if self._script is None:
            self._script = optimal_script(self.base, self.task_plan, self.office, ctx.ltm, self.log)
            batch = next(self._script)
        else:
            previous = ctx.stm.trace.steps[-2].results if len(ctx.stm.trace.steps) > 1 else []
            try:
                batch = self._script.send(_feedback(previous))
            except StopIteration as exc:
                raise ReasonerError("the optimal policy ran past its stop") from exc
        return Decision(thought="optimal policy", actions=batch)

    async def reflect(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection:
        return Reflection(verdict="Y" if all_ok(results) else "N", reason="as the policy expected")


def _feedback(results: list[ActionResult]) -> Feedback:
    repliers: list[str] = []
    for r in results:
        if r.action.type == "wait" and r.ok:
            replies = r.data.get("replies", [])
            if isinstance(replies, list):
                repliers.extend(str(p) for p in replies)
    return Feedback(tuple(repliers), ok=all_ok(results))
