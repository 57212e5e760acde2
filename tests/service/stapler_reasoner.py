"""A deterministic stand-in for the embedded reasoner, for the service's end-to-end tests.

It fetches a stapler for the requester: asks the known owners in order (skipping those memory
believes unavailable), and once one agrees runs the hand-over. Its decisions depend only on
the instruction's memory, so a resumed instruction decides the same actions again.
Used until ``assistantx.agents.symbolic.build_factory`` exists; loaded through
``ASSISTANTX_REASONER_BUILDER=service.stapler_reasoner:build_factory`` (with tests/ on PYTHONPATH).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from assistantx.agents.base import AgentContext, Reasoner
from assistantx.core.actions import Action, Inform, Inquire, Move, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.trace import (
    ActionResult,
    AgentCall,
    Percept,
    Plan,
    SubGoal,
)
from assistantx.memory.updates import AvailabilityUpdate, MemoryUpdate
from helpers.scripted_reasoner import ScriptedReasoner


def _done(ctx: AgentContext, kind: str, ok: bool = True, **match: str) -> bool:
    for r in ctx.stm.trace.actions():
        a = r.action
        if r.ok == ok and a.type == kind and all(getattr(a, k) == v for k, v in match.items()):
            return not r.refused
    return False


def _unanswered(ctx: AgentContext, results: list[ActionResult]) -> list[MemoryUpdate]:
    """Whoever was asked in a step whose wait timed out is believed unavailable."""
    if not any(r.action.type == "wait" and not r.ok for r in results):
        return []
    return [
        AvailabilityUpdate(person=r.action.contact, available=False, evidence="no answer")
        for r in results
        if isinstance(r.action, Inquire)
    ]


class StaplerReasoner(ScriptedReasoner):
    """A policy instead of a script: each decision is derived from the instruction's memory."""

    name = "stapler"

    def __init__(self) -> None:
        super().__init__([], updates=_unanswered)

    def _lender(self, ctx: AgentContext) -> str | None:
        for turn in ctx.stm.dialogue:
            if turn.direction == "in" and turn.person != ctx.stm.requester:
                return turn.person
        return None

    async def perceive(self, ctx: AgentContext) -> Percept:
        ctx.record(AgentCall(agent="perception", latency_s=0.001))
        return Percept(summary="a stapler for the requester", items=["stapler"])

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        return Plan(goal="bring a stapler", subgoals=[SubGoal(description="find a lender")])

    def next_actions(self, ctx: AgentContext) -> list[Action]:
        me = ctx.stm.requester
        lender = self._lender(ctx)
        actions: list[Action]
        if lender is None:
            asked = {t.person for t in ctx.stm.dialogue if t.direction == "out" and t.question_id}
            owners = [
                o
                for o in ctx.ltm.owners("stapler")
                if o != me and ctx.ltm.availability(o) != "unavailable"
            ]
            todo = [o for o in owners if o not in asked]
            if not todo:
                actions = [Stop(outcome="unachievable", summary="Nobody can lend a stapler.")]
            else:
                actions = [
                    Inquire(contact=todo[0], question="Could you lend me your stapler?"),
                    Wait(reason="their answer", timeout_s=60),
                ]
        elif not _done(ctx, "wait_in_place", person=lender):
            if not _done(ctx, "send_qr", contact=lender):
                actions = [
                    Inform(contact=lender, content="The robot is coming for your stapler."),
                    Move(place=lender),
                    SendQR(contact=lender, item=f"stapler:{lender}"),
                ]
            else:
                actions = [WaitInPlace(person=lender, timeout_s=3600)]
        elif not _done(ctx, "wait_in_place", person=me):
            if not _done(ctx, "send_qr", contact=me):
                actions = [
                    Move(place=me),
                    SendQR(contact=me, item=f"stapler:{lender}", purpose="collect"),
                ]
            else:
                actions = [WaitInPlace(person=me, timeout_s=3600)]
        else:
            actions = [Stop(outcome="done", summary=f"{lender}'s stapler is in your hands.")]
        return actions


def build_factory(office: Any, settings: Any) -> Callable[[], Reasoner]:
    return StaplerReasoner
