"""The paper's baselines as Reasoners, each with its own prompts under ``prompts/baselines/``.

They are LLM-only methods. All of them see the same rendered memory (the part of long-term
memory the task touches, as PPDR's agents do, capped to the context; the instruction,
dialogue and previous steps) and answer with a ``Decision``; they differ in
how they think and what they carry between steps:

- ``direct``: the next actions, no reasoning asked for.
- ``cot``: chain of thought in ``thought``, then the actions.
- ``react``: one thought and exactly one action per turn; the observation comes back next turn.
- ``reflexion``: ReAct, plus after a step that did not go as hoped a self-reflection call whose
  lesson is kept and shown to every later decision.
- ``mobile_agent_v2``: a planning agent (progress so far, what to focus on), a decision agent,
  and a reflection agent judging each step (its verdict reaches the next plan and decision).

Their perception and planning (except Mobile-Agent-v2's) cost no call; the loop's grounding,
repetition refusal and feedback are the same as for PPDR, so the comparison is fair.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Literal, TypeVar

from pydantic import BaseModel, Field

from assistantx.agents.base import AgentContext
from assistantx.agents.baseline_names import BaselineName
from assistantx.agents.llm import (
    ModelReasoner,
    SharedModel,
    check_actions,
    require_model,
    schema_text,
)
from assistantx.agents.llm.prompts import DEFAULT_PROMPTS, PromptTemplate, load_prompt
from assistantx.core.errors import ModelOutputError
from assistantx.core.ports.model import ChatModel
from assistantx.core.settings import Settings
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
from assistantx.memory.focus import FocusBudget, focus_budget

OutputT = TypeVar("OutputT", bound=BaseModel)


class Lesson(BaseModel):
    """Reflexion's self-reflection: what went wrong and what to do differently."""

    lesson: str = Field(min_length=1, max_length=1000)


class Progress(BaseModel):
    """Mobile-Agent-v2's planning output."""

    completed: str = Field(default="", max_length=2000, description="what is done so far")
    next_focus: str = Field(min_length=1, max_length=1000, description="what to do next")


class StepJudgement(BaseModel):
    """Mobile-Agent-v2's reflection output."""

    verdict: Literal["Y", "N"]
    reason: str = Field(min_length=1, max_length=2000)


def _prompt_files(name: BaselineName) -> list[str]:
    if name == "reflexion":
        return ["reflexion", "reflexion_reflect"]
    if name == "mobile_agent_v2":
        return ["mobile_agent_v2_plan", "mobile_agent_v2_decide", "mobile_agent_v2_reflect"]
    return [name]


def load_baseline_prompts(
    name: BaselineName, prompts_dir: str | Path | None = None
) -> dict[str, PromptTemplate]:
    folder = Path(prompts_dir or DEFAULT_PROMPTS) / "baselines"
    return {f: load_prompt(folder / f"{f}.md", name=f"baselines/{f}") for f in _prompt_files(name)}


class BaselineReasoner(ModelReasoner):
    def __init__(
        self,
        name: BaselineName,
        shared: SharedModel,
        prompts: dict[str, PromptTemplate],
        *,
        output_retries: int = 2,
        budget: FocusBudget | None = None,
    ) -> None:
        super().__init__(shared, output_retries=output_retries, budget=budget)
        self.name = name
        self.prompts = prompts
        self.lessons: list[str] = []
        self.progress: Progress | None = None
        self.judgement: StepJudgement | None = None

    # -- the four hooks ------------------------------------------------------------------
    async def perceive(self, ctx: AgentContext) -> Percept:
        return Percept(summary="")

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        if self.name != "mobile_agent_v2":
            return Plan(goal=ctx.stm.text[:1000], subgoals=[SubGoal(description="do it")])
        self.progress = await self._call(
            ctx,
            "mobile_agent_v2_plan",
            Progress,
            memory=self.memory(ctx),
            last_judgement=self._judgement_text(),
            output_schema=schema_text(Progress),
        )
        return Plan(
            goal=ctx.stm.text[:1000],
            subgoals=[SubGoal(description=self.progress.next_focus[:500])],
            notes=self.progress.completed[:2000],
        )

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        values: dict[str, str] = {
            "memory": self.memory(ctx),
            "feedback": "\n".join(f"- {f}" for f in ctx.feedback) or "(none)",
            "action_space": ACTION_SPACE,
            "output_schema": schema_text(Decision),
        }
        prompt = self.name
        if self.name == "reflexion":
            values["lessons"] = "\n".join(f"- {x}" for x in self.lessons) or "(none yet)"
        if self.name == "mobile_agent_v2":
            prompt = "mobile_agent_v2_decide"
            values["focus"] = self.progress.next_focus if self.progress else ctx.stm.text
            values["last_judgement"] = self._judgement_text()

        def valid(decision: Decision) -> None:
            if self.name in ("react", "reflexion") and len(decision.actions) != 1:
                raise ModelOutputError("give exactly one action per turn")
            check_actions(decision.actions, ctx.resolver, ctx.stm)

        async def ask(grounded: Callable[[Decision], None]) -> Decision:
            return await self._call(ctx, prompt, Decision, check=grounded, **values)

        return await self._grounded_decision(ctx, ask, valid)

    async def reflect(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection:
        ok = all_ok(results)
        outcome = _results_text(results)
        if self.name == "reflexion" and not ok:
            lesson = await self._call(
                ctx,
                "reflexion_reflect",
                Lesson,
                memory=self.memory(ctx),
                step=outcome,
                output_schema=schema_text(Lesson),
            )
            self.lessons.append(lesson.lesson)
            return Reflection(verdict="N", reason=lesson.lesson)
        if self.name == "mobile_agent_v2":
            self.judgement = await self._call(
                ctx,
                "mobile_agent_v2_reflect",
                StepJudgement,
                memory=self.memory(ctx),
                focus=self.progress.next_focus if self.progress else ctx.stm.text,
                step=outcome,
                output_schema=schema_text(StepJudgement),
            )
            return Reflection(verdict=self.judgement.verdict, reason=self.judgement.reason)
        return Reflection(verdict="Y" if ok else "N", reason=outcome[:2000] or "nothing ran")

    # -- helpers -------------------------------------------------------------------------
    def _judgement_text(self) -> str:
        if self.judgement is None:
            return "(no step judged yet)"
        return f"{self.judgement.verdict}: {self.judgement.reason}"

    async def _call(
        self,
        ctx: AgentContext,
        prompt: str,
        output_type: type[OutputT],
        *,
        check: Callable[[OutputT], None] | None = None,
        **values: str,
    ) -> OutputT:
        messages = self.prompts[prompt].render(values)
        return await self._ask(ctx, prompt, messages, output_type, check)


def _results_text(results: list[ActionResult]) -> str:
    lines = []
    for r in results:
        status = "refused" if r.refused else ("ok" if r.ok else "failed")
        lines.append(f"{r.action.signature()} -> {status}: {r.observation}")
    return "\n".join(lines)


class BaselineFactory:
    """One reasoner per instruction, all sharing one model and the loaded prompts."""

    def __init__(
        self,
        name: BaselineName,
        model: ChatModel,
        *,
        prompts_dir: str | Path | None = None,
        output_retries: int = 2,
        budget: FocusBudget | None = None,
    ) -> None:
        self.name = name
        self.shared = SharedModel(model)
        self.prompts = load_baseline_prompts(name, prompts_dir)
        self.output_retries = output_retries
        self.budget = budget

    def __call__(self) -> BaselineReasoner:
        return BaselineReasoner(
            self.name,
            self.shared,
            self.prompts,
            output_retries=self.output_retries,
            budget=self.budget,
        )


def build_baseline_factory(
    name: BaselineName, settings: Settings, *, model: ChatModel | None = None
) -> BaselineFactory:
    return BaselineFactory(
        name,
        require_model(model, name),
        output_retries=settings.llm_output_retries,
        budget=focus_budget(settings.llm_context_tokens, settings.llm_max_tokens),
    )


ACTION_SPACE = """\
- inform {contact, content}: message a person or a group chat.
- inquire {contact, question}: ask a person or a group chat; follow it with wait. Name the
  item or the request in the question ("Could you lend <requester> your <item>?").
- forward_file {source, target}: forward the file received from source (the requester's own
  file counts as received; anyone else's must first be sent to you after you asked for it).
- send_qr {contact, item, purpose}: a one-time locker code. item is "type:owner", an item
  type of the office and a person id. purpose: deposit (put it in), collect (take it out),
  sign, seal, copy, heat (take the item out, do the facility's operation on it, put it back),
  produce (make the facility's product at the facility and put it in).
- wait {reason, timeout_s}: wait for a reply (60 s for a person); no reply = unavailable.
- move {place}: drive to a person (their desk), a facility id of the office (see memory) or
  a location id.
- wait_in_place {person, timeout_s}: stay until that person used the locker.
- stop {outcome, summary}: end; outcome done, unachievable or failed; the summary goes to
  the requester. Never claim what did not happen.
A person comes to the locker only when the robot is at their place, they hold a code, and
they were told why (an inquiry counts). When nobody in memory can help, ask a group chat."""
