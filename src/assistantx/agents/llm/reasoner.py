"""The PPDR agents as LLM agents: four prompts, one chat model, outputs checked against memory.

Each agent renders its template from ``prompts/`` (memory through the one renderer, the
upstream agents' outputs as JSON, the previous reflection and the loop's feedback, see
:mod:`.inputs`) and asks the model for its pydantic output through
:class:`~assistantx.agents.llm.model_reasoner.ModelReasoner`. What the model names is checked
against the office before anything runs (:mod:`.checks`); the names come back as ids.

The chat model is made once per factory and shared by every instruction's reasoner
(:class:`~assistantx.agents.llm.shared.SharedModel`).
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from assistantx.agents.base import AgentContext
from assistantx.agents.llm.checks import check_actions, focus_ids, ground_updates
from assistantx.agents.llm.inputs import (
    actions_text,
    feedback_text,
    json_text,
    observed_text,
    previous_plan,
    reflection_text,
    results_text,
    schema_text,
)
from assistantx.agents.llm.model_reasoner import ModelReasoner
from assistantx.agents.llm.prompts import PromptTemplate, load_prompts
from assistantx.agents.llm.shared import SharedModel, require_model
from assistantx.core.office import Office
from assistantx.core.ports.model import ChatModel, Message
from assistantx.core.settings import Settings
from assistantx.core.trace import (
    ActionResult,
    Decision,
    Observation,
    Percept,
    Plan,
    Reflection,
)
from assistantx.memory.focus import FocusBudget, focus_budget

logger = logging.getLogger(__name__)

AGENTS = ("perception", "planning", "decision", "reflection")


@dataclass(frozen=True)
class AgentPrompts:
    """The four agents' templates, loaded and checked together at start-up."""

    perception: PromptTemplate
    planning: PromptTemplate
    decision: PromptTemplate
    reflection: PromptTemplate

    @classmethod
    def load(cls, directory: str | Path | None = None) -> AgentPrompts:
        """Load from ``directory`` (default: the repository's ``prompts/``); PromptError if bad."""
        templates = load_prompts(directory, AGENTS)
        return cls(**templates)


class LLMReasoner(ModelReasoner):
    """Perception, Planning, Decision and Reflection, each one prompt and one typed output."""

    name = "llm"

    def __init__(
        self,
        shared: SharedModel,
        prompts: AgentPrompts,
        *,
        output_retries: int = 2,
        budget: FocusBudget | None = None,
    ) -> None:
        super().__init__(shared, output_retries=output_retries, budget=budget)
        self.prompts = prompts
        self._schemas = {
            "perception": schema_text(Percept),
            "planning": schema_text(Plan),
            "decision": schema_text(Decision),
            "reflection": schema_text(Reflection),
        }

    # -- the four prompts (public: the prompt-size bench and the real-server tests use them) --
    def perception_messages(self, ctx: AgentContext) -> list[Message]:
        return self.prompts.perception.render(
            memory=self.memory(ctx),
            step=ctx.step,
            previous_reflection=reflection_text(ctx.last_reflection),
            feedback=feedback_text(ctx.feedback),
            output_schema=self._schemas["perception"],
        )

    def planning_messages(self, ctx: AgentContext, percept: Percept) -> list[Message]:
        return self.prompts.planning.render(
            memory=self.memory(ctx, percept),
            percept=json_text(percept, "{}"),
            previous_plan=json_text(previous_plan(ctx.stm), "(none: this is the first step)"),
            previous_reflection=reflection_text(ctx.last_reflection),
            feedback=feedback_text(ctx.feedback),
            output_schema=self._schemas["planning"],
        )

    def decision_messages(self, ctx: AgentContext, percept: Percept, plan: Plan) -> list[Message]:
        return self.prompts.decision.render(
            memory=self.memory(ctx, percept),
            percept=json_text(percept, "{}"),
            plan=json_text(plan, "{}"),
            previous_reflection=reflection_text(ctx.last_reflection),
            feedback=feedback_text(ctx.feedback),
            output_schema=self._schemas["decision"],
        )

    def reflection_messages(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: Sequence[ActionResult],
        observed: Observation,
    ) -> list[Message]:
        return self.prompts.reflection.render(
            memory=self.memory(ctx, percept),
            percept=json_text(percept, "{}"),
            plan=json_text(plan, "{}"),
            actions=actions_text(decision),
            results=results_text(results),
            observed=observed_text(observed),
            output_schema=self._schemas["reflection"],
        )

    # -- the four agents -----------------------------------------------------------------
    async def perceive(self, ctx: AgentContext) -> Percept:
        def check(percept: Percept) -> None:
            focus_ids(percept, ctx.resolver, ctx.stm.requester)

        percept = await self._ask(
            ctx, "perception", self.perception_messages(ctx), Percept, check, schema_name="Percept"
        )
        return focus_ids(percept, ctx.resolver, ctx.stm.requester)

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        messages = self.planning_messages(ctx, percept)
        return await self._ask(ctx, "planning", messages, Plan, None, schema_name="Plan")

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        def check(decision: Decision) -> None:
            check_actions(decision.actions, ctx.resolver, ctx.stm)

        messages = self.decision_messages(ctx, percept, plan)

        async def ask(grounded: Callable[[Decision], None]) -> Decision:
            return await self._ask(
                ctx, "decision", messages, Decision, grounded, schema_name="Decision"
            )

        return await self._grounded_decision(ctx, ask, check)

    async def reflect(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection:
        def check(reflection: Reflection) -> None:
            ground_updates(reflection.updates, ctx.resolver)

        messages = self.reflection_messages(ctx, percept, plan, decision, results, observed)
        reflection = await self._ask(
            ctx, "reflection", messages, Reflection, check, schema_name="Reflection"
        )
        return reflection.model_copy(
            update={"updates": ground_updates(reflection.updates, ctx.resolver)}
        )


class LLMReasonerFactory:
    """Makes one :class:`LLMReasoner` per instruction, all sharing one model and one prompt set."""

    def __init__(
        self,
        model: ChatModel,
        prompts: AgentPrompts,
        *,
        output_retries: int,
        budget: FocusBudget | None = None,
    ) -> None:
        self.shared = SharedModel(model)
        self.prompts = prompts
        self.output_retries = output_retries
        self.budget = budget

    @property
    def model(self) -> ChatModel:
        return self.shared.model

    def __call__(self) -> LLMReasoner:
        return LLMReasoner(
            self.shared, self.prompts, output_retries=self.output_retries, budget=self.budget
        )


def build_factory(
    office: Office,
    settings: Settings,
    *,
    model: ChatModel | None = None,
    prompts_dir: str | Path | None = None,
) -> LLMReasonerFactory:
    """The LLM reasoner for ``assistantx.agents.registry`` (``office`` is unused: names resolve
    against each instruction's memory).

    The prompts are loaded and checked now, so a broken template fails at start-up.
    ``model`` is injected by the composition root; ReasonerError without one.
    """
    del office  # the resolver comes with each AgentContext
    prompts = AgentPrompts.load(prompts_dir)
    model = require_model(model, "llm")
    logger.info("LLM reasoner: %r, output retries %d", model, settings.llm_output_retries)
    return LLMReasonerFactory(
        model,
        prompts,
        output_retries=settings.llm_output_retries,
        budget=focus_budget(settings.llm_context_tokens, settings.llm_max_tokens),
    )
