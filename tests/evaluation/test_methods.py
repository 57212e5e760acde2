"""Baselines driven by the scripted LLM server, and the ablation wrappers, through the harness."""

from __future__ import annotations

import json
from typing import Any

import pytest

from assistantx.adapters.model import OpenAICompatibleModel
from assistantx.agents.ablations import NoPerception, NoPlanning, NoReflection
from assistantx.agents.base import AgentContext, Reasoner
from assistantx.agents.baseline_names import BASELINES
from assistantx.agents.baselines import BaselineFactory
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office
from assistantx.core.settings import Settings
from assistantx.core.trace import Decision, Percept, Plan
from assistantx.evaluation.dataset import OptimalReasoner, load_tasks
from assistantx.evaluation.dataset.tasks import Task
from assistantx.evaluation.episode import Episode
from assistantx.evaluation.harness import run_episode
from assistantx.evaluation.methods import MethodBuilder, MethodSpec
from assistantx.evaluation.metrics import score
from fakes.scripted_llm import ScriptedLLM


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


@pytest.fixture(scope="module")
def forward_task(office: Office) -> Task:
    tasks = load_tasks(DEFAULT_OFFICE.parent / "tasks.jsonl", office)
    return next(t for t in tasks if t.base == "b26" and not t.unavailable)  # Lee → Zhou


FORWARD = {"thought": "", "actions": [{"type": "forward_file", "source": "lee", "target": "zhou"}]}
STOP = {"thought": "", "actions": [{"type": "stop", "outcome": "done", "summary": "Sent."}]}


def _script(llm: ScriptedLLM, name: str) -> None:
    if name == "mobile_agent_v2":
        llm.script(
            "mobile_agent_v2_plan",
            {"completed": "", "next_focus": "forward the slides"},
            {"completed": "forwarded", "next_focus": "tell Lee"},
        )
        llm.script("mobile_agent_v2_decide", FORWARD, STOP)
        llm.script("mobile_agent_v2_reflect", {"verdict": "Y", "reason": "Zhou got the file"})
        return
    llm.script(name, "I'll forward it: " + str(FORWARD).replace("'", '"'), STOP)


class _Builder(MethodBuilder):
    """The harness's builder with the baseline pointed at the scripted server."""

    def __init__(self, office: Office, name: str, base_url: str) -> None:
        self.spec = MethodSpec(name)
        self.office = office
        self._shared = BaselineFactory(name, OpenAICompatibleModel(base_url, "scripted"))  # type: ignore[arg-type]


@pytest.mark.parametrize("name", BASELINES)
async def test_scripted_model_drives_each_baseline(
    name: str, office: Office, forward_task: Task, scripted_llm: ScriptedLLM
) -> None:
    _script(scripted_llm, name)
    episode = await run_episode(
        forward_task, 0, office, _Builder(office, name, scripted_llm.base_url)
    )
    s = score(episode)
    assert episode.trace.outcome == "done" and s.sr == 1.0 and s.rr == 0.0
    assert s.llm_calls == (5 if name == "mobile_agent_v2" else 2)
    assert scripted_llm.pending() == 0
    agents = {call.agent for step in episode.trace.steps for call in step.calls}
    assert agents == ({name} if name != "mobile_agent_v2" else {
        "mobile_agent_v2_plan", "mobile_agent_v2_decide", "mobile_agent_v2_reflect"})  # fmt: skip


async def test_reflexion_keeps_a_lesson_after_a_failure(
    office: Office, forward_task: Task, scripted_llm: ScriptedLLM
) -> None:
    wrong = {
        "thought": "",
        "actions": [{"type": "forward_file", "source": "zhou", "target": "lee"}],
    }
    scripted_llm.script("reflexion", wrong, FORWARD, STOP)
    scripted_llm.script("reflexion_reflect", {"lesson": "Forward Lee's own file, not Zhou's."})
    episode = await run_episode(
        forward_task, 0, office, _Builder(office, "reflexion", scripted_llm.base_url)
    )
    assert episode.trace.outcome == "done"
    assert episode.trace.steps[0].reflection is not None
    assert "Lee's own file" in episode.trace.steps[0].reflection.reason
    bodies = [json.dumps(r.body) for r in scripted_llm.requests]
    later = [b for b in bodies if "LESSONS" in b and "reflexion_reflect" not in b]
    assert any("Lee's own file" in b for b in later[1:])
    assert score(episode).cta is not None and score(episode).cta < 1.0


class _Recording(Reasoner):
    """Wraps the optimal policy and records what Decision was given."""

    name = "recording"

    def __init__(self, inner: OptimalReasoner) -> None:
        self.inner = inner
        self.seen: list[tuple[Percept, Plan]] = []

    async def perceive(self, ctx: AgentContext) -> Percept:
        return Percept(people=["lee"], summary="focus on Lee")

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        return await self.inner.plan(ctx, percept)

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        self.seen.append((percept, plan))
        return await self.inner.decide(ctx, percept, plan)

    async def reflect(self, ctx: AgentContext, *args: Any) -> Any:
        return await self.inner.reflect(ctx, *args)


class _AblationBuilder(MethodBuilder):
    def __init__(self, office: Office, wrap: Any, made: list[_Recording]) -> None:
        self.spec = MethodSpec("optimal")
        self.office = office
        self.wrap, self.made = wrap, made

    def factory(self, task: Task) -> Any:
        def make() -> Reasoner:
            inner = _Recording(
                OptimalReasoner.for_task(
                    self.office, task.id, task.requester, task.instruction, task.spec
                )
            )
            self.made.append(inner)
            return self.wrap(inner)

        return make


@pytest.mark.parametrize("wrap", [NoPerception, NoPlanning, NoReflection])
async def test_ablations_change_only_their_agent(
    wrap: Any, office: Office, forward_task: Task
) -> None:
    made: list[_Recording] = []
    episode: Episode = await run_episode(
        forward_task, 0, office, _AblationBuilder(office, wrap, made)
    )
    assert episode.trace.outcome == "done"
    percept, plan = made[0].seen[0]
    assert (percept.people == []) == (wrap is NoPerception)
    assert (plan.subgoals[0].description == "carry out the instruction") == (wrap is NoPlanning)
    reasons = [s.reflection.reason for s in episode.trace.steps if s.reflection]
    assert any("ablated" in r for r in reasons) == (wrap is NoReflection)


def test_unknown_method_and_missing_reasoner_are_clear(office: Office) -> None:
    from assistantx.core.errors import ReasonerError

    with pytest.raises(ReasonerError, match="unknown method"):
        MethodBuilder(MethodSpec("magic"), office, Settings())
