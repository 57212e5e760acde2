"""The embedded symbolic reasoner: a deterministic PPDR that needs no LLM.

One instance per instruction (the factory makes one each time). Everything it decides is
derived from memory at each step: the frame from the instruction and the requester's answers
to clarifying questions, the progress from the dialogue, the codes and the trace. Within one
step, Perception computes the view that Planning and Decision then use. Each agent call is
recorded like an LLM call (agent name, latency), with zero tokens.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Callable
from dataclasses import dataclass

from assistantx.agents.base import AgentContext, Reasoner
from assistantx.agents.symbolic.answers import says_not_known
from assistantx.agents.symbolic.decision import Decider
from assistantx.agents.symbolic.evidence import Evidence, gather
from assistantx.agents.symbolic.perception import perceive
from assistantx.agents.symbolic.planning import Agenda, Planner
from assistantx.agents.symbolic.reading.parser import InstructionParser, TaskFrame, shared_parser
from assistantx.agents.symbolic.reflection import Reflector
from assistantx.agents.symbolic.roles import Roles
from assistantx.core import language
from assistantx.core.actions import Action, Stop
from assistantx.core.office import Office
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
from assistantx.core.updates import AvailabilityUpdate, MemoryUpdate
from assistantx.memory.short_term import ShortTermMemory

logger = logging.getLogger(__name__)

MODEL = "symbolic"
DistanceFn = Callable[[str, str], float]


@dataclass
class _View:
    evidence: Evidence
    frame: TaskFrame
    agenda: Agenda | None


class SymbolicReasoner(Reasoner):
    name = "symbolic"

    def __init__(
        self,
        office: Office,
        *,
        distance: DistanceFn | None = None,
        parser: InstructionParser | None = None,
    ) -> None:
        self.office = office
        self.parser = parser or InstructionParser(office)
        self.roles = Roles(office, distance or office.distance)
        self.planner = Planner(office, self.roles)
        self.decider = Decider(office, self.roles)
        self.reflector = Reflector(self.roles)
        self._frames: dict[tuple[str, ...], TaskFrame] = {}
        self._view: _View | None = None

    # -- understanding -------------------------------------------------------------------
    def frame(self, stm: ShortTermMemory) -> TaskFrame:
        """The frame from the instruction and the first answer to each clarifying question;
        an answer that only says they do not know is no answer (the question stays open)."""
        answers = [a for a in stm.requester_answers() if not says_not_known(a)]
        key = (stm.text, *answers)
        if key not in self._frames:
            self._frames[key] = self.parser.parse_with_answers(stm.text, stm.requester, answers)
        return self._frames[key]

    def _compute(self, ctx: AgentContext) -> _View:
        frame = self.frame(ctx.stm)
        ev = self._gather(ctx.stm, frame)
        agenda = self.planner.agenda(frame, ctx.ltm, ev, ctx.now) if frame.understood else None
        return _View(ev, frame, agenda)

    def _gather(self, stm: ShortTermMemory, frame: TaskFrame) -> Evidence:
        """The evidence, with what the requester stated in the request (the frame's hints)."""
        ev = gather(stm, self.office)
        for h in frame.hints:
            if h.kind == "availability" and h.value == "away":
                ev.said_away[h.person] = h.said
            if h.kind == "condition" and h.item_type:
                ev.said_unusable[(h.person, h.item_type)] = h.value
        return ev

    def _current(self, ctx: AgentContext) -> _View:
        if self._view is None:
            self._view = self._compute(ctx)
        return self._view

    # -- the four agents -----------------------------------------------------------------
    async def perceive(self, ctx: AgentContext) -> Percept:
        started = time.perf_counter()
        self._view = self._compute(ctx)
        v = self._view
        percept = perceive(v.frame, v.agenda, v.evidence, ctx.ltm, self.roles)
        _record(ctx, "perception", started)
        return percept

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        started = time.perf_counter()
        v = self._current(ctx)
        notes = ""
        if ctx.last_reflection is not None and ctx.last_reflection.verdict == "N":
            notes = f"re-planned after: {ctx.last_reflection.reason}"
        if v.frame.decline is not None:
            plan = Plan(
                goal=f"decline the request {ctx.stm.text!r}",
                subgoals=[SubGoal(description=f"tell {ctx.stm.requester}: {v.frame.decline}")],
                notes=notes,
            )
        elif v.agenda is None:
            plan = Plan(
                goal=f"understand the request {ctx.stm.text!r}",
                subgoals=[
                    SubGoal(description=f"ask {ctx.stm.requester}: {v.frame.question}"),
                    SubGoal(description="do what they meant"),
                ],
                notes=notes,
            )
        else:
            plan = self.planner.plan_model(v.agenda, notes)
        _record(ctx, "planning", started)
        return plan

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        started = time.perf_counter()
        v = self._current(ctx)
        if v.frame.decline is not None:
            thought = f"nothing to do: {v.frame.explain()}"
            actions: list[Action] = [
                Stop(outcome=v.frame.decline_outcome, summary=v.frame.decline[:2000])
            ]
        elif v.agenda is None:
            thought, actions = self.decider.clarify(
                v.frame.question or "", v.evidence, ctx.stm.text
            )
        else:
            thought, actions = self.decider.decide(v.agenda, v.evidence)
        if ctx.feedback:
            thought += " | feedback: " + " ".join(ctx.feedback)
        self._view = None  # the next step starts from fresh memory
        _record(ctx, "decision", started)
        return Decision(thought=thought[:2000], actions=actions)

    async def reflect(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection:
        started = time.perf_counter()
        before = self._last_evidence(ctx, results)
        after = gather(ctx.stm, self.office)
        frame = self.frame(ctx.stm)
        roles = (
            [r for c in self.planner.compile(frame) for r in c.roles] if frame.understood else []
        )
        reflection = self.reflector.reflect(roles, before, after, results, observed)
        if not any(s.index < ctx.step for s in ctx.stm.trace.steps):
            reflection = _with_hints(reflection, frame)
        _record(ctx, "reflection", started)
        return reflection

    def _last_evidence(self, ctx: AgentContext, results: list[ActionResult]) -> Evidence:
        """The evidence as it stood before this step's actions (results taken out)."""
        stm = ctx.stm.model_copy(deep=False)
        trace = stm.trace.model_copy(deep=False)
        trace.steps = [s for s in stm.trace.steps if s.index < ctx.step]
        stm.trace = trace
        return gather(stm, self.office)


def _with_hints(reflection: Reflection, frame: TaskFrame) -> Reflection:
    """After the first step, memory takes in what the requester stated ("Wang is away")."""
    said: list[MemoryUpdate] = [
        AvailabilityUpdate(
            person=h.person,
            available=h.value == "here",
            evidence=f"{frame.requester} said: {h.said[:900]!r}",
        )
        for h in frame.hints
        if h.kind == "availability"
    ]
    if not said:
        return reflection
    updates = [*said, *reflection.updates][:20]
    return reflection.model_copy(update={"updates": updates})


def _record(ctx: AgentContext, agent: str, started: float) -> None:
    ctx.record(
        AgentCall(agent=agent, model=MODEL, llm=False, latency_s=time.perf_counter() - started)
    )


def build_factory(office: Office, settings: object) -> Callable[[], Reasoner]:
    """A factory making one SymbolicReasoner per instruction (the parser is shared, also
    with the runtime's consent check and request recognizer: ``shared_parser``)."""
    del settings  # nothing to configure: no model, no network
    parser = shared_parser(office)
    # Built in the service's warm-up thread: the reader's tables load there, not at the
    # first instruction, on the loop.
    language.load_tables()
    distance = office.distance

    def make() -> Reasoner:
        return SymbolicReasoner(office, distance=distance, parser=parser)

    return make
