"""The inference trace: what each agent produced at each step, and what happened.

One format for every reasoner (LLM agents, the embedded symbolic one, the baselines), so the
evaluator, the REST API and the dashboard read them alike.
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, Field

from assistantx.core.actions import Action, Outcome
from assistantx.core.dialogue import DialogueTurn
from assistantx.core.updates import AppliedUpdate, MemoryUpdate


class Percept(BaseModel):
    """The focus content: what in memory matters for the instruction right now."""

    people: list[str] = Field(default_factory=list, description="person ids in focus")
    items: list[str] = Field(default_factory=list, description="item ids or item types")
    places: list[str] = Field(default_factory=list, description="location/facility ids")
    groups: list[str] = Field(default_factory=list, description="group chat ids")
    summary: str = Field(default="", max_length=4000, description="what matters and why")


class SubGoal(BaseModel):
    description: str = Field(min_length=1, max_length=500)
    done: bool = False


class Plan(BaseModel):
    """The hierarchical plan: the goal split into ordered sub-goals with progress."""

    goal: str = Field(min_length=1, max_length=1000)
    subgoals: list[SubGoal] = Field(min_length=1, max_length=30)
    notes: str = Field(default="", max_length=2000)

    @property
    def current(self) -> SubGoal | None:
        return next((s for s in self.subgoals if not s.done), None)


class Decision(BaseModel):
    """The next action(s) for the first unmet sub-goal."""

    thought: str = Field(default="", max_length=2000)
    actions: list[Action] = Field(min_length=1, max_length=4)


class Reflection(BaseModel):
    """Did the step go as expected (Y/N), why, and what memory should now believe."""

    verdict: Literal["Y", "N"]
    reason: str = Field(min_length=1, max_length=2000)
    updates: list[MemoryUpdate] = Field(default_factory=list, max_length=20)


class ActionResult(BaseModel):
    action: Action
    ok: bool
    observation: str = Field(description="what happened, in words")
    refused: bool = Field(default=False, description="not executed (repetition, grounding)")
    error: str | None = None
    started_at: float
    ended_at: float
    data: dict[str, Any] = Field(default_factory=dict)


def all_ok(results: list[ActionResult]) -> bool:
    """Whether a batch did anything and every action of it succeeded."""
    return bool(results) and all(r.ok for r in results)


class AgentCall(BaseModel):
    """Accounting of one agent call (LLM or embedded)."""

    agent: str
    model: str | None = None
    llm: bool = Field(default=True, description="False for the embedded, model-free agents")
    prompt_tokens: int = 0
    completion_tokens: int = 0
    latency_s: float = 0.0
    attempts: int = 1
    estimated: bool = False


class Observation(BaseModel):
    """ΔM: what changed in the world as the assistant saw it during a step."""

    messages: list[DialogueTurn] = Field(default_factory=list, description="new inbound turns")
    robot_place: str | None = None
    moved: bool = False
    locker_contents: list[str] = Field(default_factory=list)
    locker_changed: bool = False


class TraceStep(BaseModel):
    index: int
    started_at: float
    ended_at: float | None = None
    percept: Percept | None = None
    plan: Plan | None = None
    decision: Decision | None = None
    results: list[ActionResult] = Field(default_factory=list)
    observed: Observation | None = None
    reflection: Reflection | None = None
    applied: list[AppliedUpdate] = Field(
        default_factory=list, description="memory updates from the reflection"
    )
    feedback: list[str] = Field(default_factory=list, description="errors fed back to agents")
    calls: list[AgentCall] = Field(default_factory=list)
    queue: list[str] = Field(default_factory=list, description="waiting for robot/locker lease")


class Usage(BaseModel):
    calls: int = Field(default=0, description="agent calls of any kind")
    llm_calls: int = Field(default=0, description="calls that went to a language model")
    prompt_tokens: int = 0
    completion_tokens: int = 0
    latency_s: float = 0.0
    estimated: bool = Field(
        default=False, description="some token counts are estimates: the server sent none"
    )
    by_agent: dict[str, dict[str, float]] = Field(default_factory=dict)

    def add(self, call: AgentCall) -> None:
        self.calls += 1
        self.llm_calls += call.attempts if call.llm else 0  # every request, repairs included
        self.prompt_tokens += call.prompt_tokens
        self.completion_tokens += call.completion_tokens
        self.latency_s += call.latency_s
        self.estimated = self.estimated or call.estimated
        agent = self.by_agent.setdefault(
            call.agent, {"calls": 0, "prompt_tokens": 0, "completion_tokens": 0, "latency_s": 0}
        )
        agent["calls"] += 1
        agent["prompt_tokens"] += call.prompt_tokens
        agent["completion_tokens"] += call.completion_tokens
        agent["latency_s"] += call.latency_s


class Trace(BaseModel):
    instruction_id: str
    requester: str
    text: str
    reasoner: str
    started_at: float
    ended_at: float | None = None
    steps: list[TraceStep] = Field(default_factory=list)
    outcome: Outcome | None = None
    summary: str | None = None
    cancelled: bool = Field(
        default=False, description="a person cancelled it (its outcome then reads failed)"
    )
    usage: Usage = Field(default_factory=Usage)

    def actions(self) -> list[ActionResult]:
        return [r for s in self.steps for r in s.results]
