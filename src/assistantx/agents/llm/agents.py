"""The PPDR agents as LLM agents: four prompts, one chat model, outputs checked against memory.

Each agent renders its template from ``prompts/`` (memory through the one renderer, the
upstream agents' outputs as JSON, the previous reflection and the loop's feedback) and asks
the model for its pydantic output with :func:`~assistantx.adapters.model.structured_call`. What the
model names is checked against the office before anything runs:

- Perception's focus (people, places, groups, items) must resolve; it is returned with ids,
  and the requester is added to a non-empty focus, because later agents see only the people
  in focus (an empty focus shows everyone);
- every action of a Decision must ground (``Resolver.ground``); a ``stop`` must be the last
  action; a QR code that the person already holds unused may not be sent again;
- Reflection's memory updates must name known people, item types, items and places.

A failed check is fed back to the model as its error, up to ``settings.llm_output_retries``
times; then :class:`~assistantx.core.errors.ModelBehaviorError` ends the instruction (the loop
tells the requester). One :class:`~assistantx.core.trace.AgentCall` per agent call (its repairs
included) goes to ``ctx.record``, so tokens and latency land in the trace.

The chat model is made once per factory and shared by every instruction's reasoner: the
first reasoner to start opens it, the last to stop closes it. A reasoner that is used
without ``start()`` starts itself on its first call (and then holds the model until its
``stop()``).
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TypeVar

from pydantic import BaseModel

from assistantx.adapters.model import (
    Attempt,
    ChatModel,
    ChatRequest,
    ChatResponse,
    Message,
    OpenAICompatibleModel,
    structured_call,
)
from assistantx.adapters.model.schema import schema_outline
from assistantx.agents.base import AgentContext, Reasoner
from assistantx.agents.llm.prompts import PromptTemplate, load_prompts
from assistantx.core.actions import Action, SendQR, Stop
from assistantx.core.errors import (
    GroundingError,
    ModelBehaviorError,
    ReasonerError,
    UnknownNameError,
)
from assistantx.core.office import Office
from assistantx.core.ports.model import LLMCallFailed
from assistantx.core.settings import Settings
from assistantx.core.trace import (
    ActionResult,
    AgentCall,
    Decision,
    Observation,
    Percept,
    Plan,
    Reflection,
)
from assistantx.memory.focus import (
    FocusBudget,
    focus_budget,
    merge_focus,
    render_focused,
    task_focus,
)
from assistantx.memory.render import quote
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from assistantx.memory.updates import (
    AvailabilityUpdate,
    ItemLocationUpdate,
    MemoryUpdate,
    OwnershipUpdate,
)

logger = logging.getLogger(__name__)

AGENTS = ("perception", "planning", "decision", "reflection")
LOCKER_HOLDER = "locker"

OutputT = TypeVar("OutputT", bound=BaseModel)


# -- prompts ---------------------------------------------------------------------------------


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


def schema_text(model: type[BaseModel]) -> str:
    """The shape of a pydantic model's output for a prompt: a compact outline, not the full
    schema. The schema itself goes with the request; the client pastes it into the prompt only
    when the server cannot enforce it, so a prompt never carries it twice (it was 4.7k of
    Decision's 10.2k-character system prompt)."""
    return schema_outline(model)


# -- the shared model ------------------------------------------------------------------------


class SharedModel:
    """One chat model used by many reasoners: opened by the first user, closed by the last."""

    def __init__(self, model: ChatModel) -> None:
        self.model = model
        self._users = 0
        self._lock = asyncio.Lock()

    @property
    def users(self) -> int:
        return self._users

    async def acquire(self) -> None:
        async with self._lock:
            if self._users == 0:
                await self.model.start()
            self._users += 1

    async def release(self) -> None:
        async with self._lock:
            if self._users == 0:
                return
            self._users -= 1
            if self._users == 0:
                await self.model.stop()


# -- checks of the model's outputs against memory --------------------------------------------


def focus_ids(percept: Percept, resolver: Resolver, requester: str) -> Percept:
    """The percept with every name replaced by its id (and the requester added to a non-empty
    list of people); GroundingError when a name does not resolve."""
    people = [resolver.person(p) for p in percept.people]
    if people and requester not in people:  # no people at all: no filter, everyone is shown
        people.insert(0, requester)
    places = [_place_or_facility(resolver, p) for p in percept.places]
    groups = [resolver.group(g) for g in percept.groups]
    items = [_item_or_type(resolver, i) for i in percept.items]
    return percept.model_copy(
        update={
            "people": list(dict.fromkeys(people)),
            "places": list(dict.fromkeys(places)),
            "groups": list(dict.fromkeys(groups)),
            "items": list(dict.fromkeys(items)),
        }
    )


def _place_or_facility(resolver: Resolver, name: str) -> str:
    """A facility id when the name is a facility (the renderer filters facilities by id)."""
    try:
        return resolver.facility(name)
    except GroundingError:
        return resolver.place(name)


def _item_or_type(resolver: Resolver, name: str) -> str:
    try:
        return resolver.item(name)
    except UnknownNameError:
        if ":" in name:
            raise
        return resolver.item_type(name)


def check_actions(actions: Sequence[Action], resolver: Resolver, stm: ShortTermMemory) -> None:
    """Raise with a message for the model when an action cannot run as proposed."""
    for index, action in enumerate(actions):
        where = f"actions[{index}] ({action.type})"
        try:
            grounded = resolver.ground(action)
        except GroundingError as exc:
            raise type(exc)(exc.kind, exc.name, f"{where}: {exc}", exc.candidates) from exc
        if isinstance(grounded, Stop) and index != len(actions) - 1:
            raise ValueError(f"{where}: stop ends the instruction, so it must be the last action")
        if isinstance(grounded, SendQR):
            for code in stm.embodied.codes:
                if not (code.used or code.revoked) and (code.person, code.item, code.purpose) == (
                    grounded.contact,
                    grounded.item,
                    grounded.purpose,
                ):
                    raise ValueError(
                        f"{where}: {grounded.contact} already holds an unused QR code to "
                        f"{grounded.purpose} {grounded.item}; never resend the same QR code"
                    )


def ground_update(update: MemoryUpdate, resolver: Resolver) -> MemoryUpdate:
    """The update with ids for every name; GroundingError when something is unknown."""
    if isinstance(update, AvailabilityUpdate):
        return update.model_copy(update={"person": resolver.person(update.person)})
    if isinstance(update, OwnershipUpdate):
        return update.model_copy(
            update={
                "person": resolver.person(update.person),
                "item_type": resolver.item_type(update.item_type),
            }
        )
    return update.model_copy(
        update={"item": resolver.item(update.item), "holder": _holder(update, resolver)}
    )


def _holder(update: ItemLocationUpdate, resolver: Resolver) -> str:
    if update.holder.strip().lower() == LOCKER_HOLDER:
        return LOCKER_HOLDER
    try:
        return resolver.person(update.holder)
    except GroundingError:
        return resolver.place(update.holder)


def ground_updates(updates: Sequence[MemoryUpdate], resolver: Resolver) -> list[MemoryUpdate]:
    grounded = []
    for index, update in enumerate(updates):
        try:
            grounded.append(ground_update(update, resolver))
        except GroundingError as exc:
            raise type(exc)(
                exc.kind, exc.name, f"updates[{index}] ({update.kind}): {exc}", exc.candidates
            ) from exc
    return grounded


# -- rendering of the agents' inputs ---------------------------------------------------------


def _json(model: BaseModel | None, empty: str) -> str:
    return model.model_dump_json(indent=1) if model is not None else empty


def _reflection_text(reflection: Reflection | None) -> str:
    if reflection is None:
        return "(none: this is the first step)"
    return f"verdict {reflection.verdict}: {quote(reflection.reason, 2000)}"


def _feedback_text(feedback: Sequence[str]) -> str:
    if not feedback:
        return "(none)"
    # Feedback can echo names the model made up; quote it like any other untrusted text.
    return "\n".join(f"- {quote(line, 1000)}" for line in feedback)


def _previous_plan(stm: ShortTermMemory) -> Plan | None:
    for step in reversed(stm.trace.steps[:-1]):
        if step.plan is not None:
            return step.plan
    return None


def _actions_text(decision: Decision) -> str:
    return "\n".join(f"- {a.signature()}" for a in decision.actions)


def _results_text(results: Sequence[ActionResult]) -> str:
    if not results:
        return "(no action ran)"
    lines = []
    for r in results:
        status = "refused" if r.refused else ("ok" if r.ok else "failed")
        lines.append(f"- {r.action.signature()} -> {status}: {quote(r.observation, 600)}")
    return "\n".join(lines)


def _observed_text(observed: Observation) -> str:
    lines = [
        f"robot at {observed.robot_place or 'unknown'} (moved: {str(observed.moved).lower()})",
        f"locker holds {', '.join(observed.locker_contents) or 'nothing'} "
        f"(changed: {str(observed.locker_changed).lower()})",
    ]
    if not observed.messages:
        lines.append("new messages: none")
    for turn in observed.messages:
        files = f" [files: {', '.join(turn.files)}]" if turn.files else ""
        lines.append(f"new message: {turn.person} in {turn.chat.id}: {quote(turn.text)}{files}")
    return "\n".join(lines)


# -- a reasoner on a shared model -------------------------------------------------------------


class ModelReasoner(Reasoner):
    """A reasoner whose agents are structured calls to a shared chat model, accounted in the
    trace. Holds the shared model from ``start`` to ``stop`` (both idempotent)."""

    def __init__(
        self,
        shared: SharedModel,
        *,
        output_retries: int = 2,
        budget: FocusBudget | None = None,
    ) -> None:
        if output_retries < 0:
            raise ValueError("output_retries must be >= 0")
        self.shared = shared
        self.output_retries = output_retries
        self.budget = budget or focus_budget(8192, 1024)
        self._holding = False

    def memory(self, ctx: AgentContext, percept: Percept | None = None) -> str:
        """The memory an agent sees: the task's focus (merged with the model's percept),
        capped to fit the context; never the whole office."""
        focus = merge_focus(percept, task_focus(ctx.ltm, ctx.stm))
        return render_focused(ctx.ltm, ctx.stm, focus, self.budget)

    async def start(self) -> None:
        if not self._holding:
            await self.shared.acquire()
            self._holding = True

    async def stop(self) -> None:
        if self._holding:
            self._holding = False
            await self.shared.release()

    async def _ask(
        self,
        ctx: AgentContext,
        agent: str,
        messages: list[Message],
        output_type: type[OutputT],
        check: Callable[[OutputT], None] | None,
        *,
        schema_name: str | None = None,
    ) -> OutputT:
        """One structured call, its attempts recorded on ``ctx`` even when it gives up."""
        await self.start()
        request = ChatRequest(
            messages=tuple(messages),
            agent=agent,
            schema_name=schema_name,
            instruction_id=ctx.stm.instruction_id,
            step=ctx.step,
        )
        try:
            result = await structured_call(
                self.shared.model, request, output_type, check, max_retries=self.output_retries
            )
        except ModelBehaviorError as exc:
            attempts = [a for a in exc.attempts if isinstance(a, Attempt)]
            if attempts:
                ctx.record(agent_call(agent, attempts))
            raise
        except LLMCallFailed as exc:
            # The server read the prompt (and maybe generated) before failing: count it.
            earlier = [a for a in exc.attempts if isinstance(a, Attempt)]
            failed = Attempt(
                response=ChatResponse(
                    text="",
                    usage=exc.usage,
                    latency_s=exc.latency_s,
                    model=exc.model,
                    retries=exc.retries,
                ),
                error=str(exc),
            )
            ctx.record(agent_call(agent, [*earlier, failed]))
            raise
        ctx.record(agent_call(agent, result.attempts))
        return result.output


# -- the reasoner ----------------------------------------------------------------------------


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
            previous_reflection=_reflection_text(ctx.last_reflection),
            feedback=_feedback_text(ctx.feedback),
            output_schema=self._schemas["perception"],
        )

    def planning_messages(self, ctx: AgentContext, percept: Percept) -> list[Message]:
        return self.prompts.planning.render(
            memory=self.memory(ctx, percept),
            percept=_json(percept, "{}"),
            previous_plan=_json(_previous_plan(ctx.stm), "(none: this is the first step)"),
            previous_reflection=_reflection_text(ctx.last_reflection),
            feedback=_feedback_text(ctx.feedback),
            output_schema=self._schemas["planning"],
        )

    def decision_messages(self, ctx: AgentContext, percept: Percept, plan: Plan) -> list[Message]:
        return self.prompts.decision.render(
            memory=self.memory(ctx, percept),
            percept=_json(percept, "{}"),
            plan=_json(plan, "{}"),
            previous_reflection=_reflection_text(ctx.last_reflection),
            feedback=_feedback_text(ctx.feedback),
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
            percept=_json(percept, "{}"),
            plan=_json(plan, "{}"),
            actions=_actions_text(decision),
            results=_results_text(results),
            observed=_observed_text(observed),
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
        return await self._ask(ctx, "decision", messages, Decision, check, schema_name="Decision")

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


def agent_call(agent: str, attempts: Sequence[Attempt]) -> AgentCall:
    """The trace's accounting of one agent call: every attempt's tokens and latency summed."""
    return AgentCall(
        agent=agent,
        model=attempts[-1].response.model if attempts else None,
        prompt_tokens=sum(a.response.usage.prompt_tokens for a in attempts),
        completion_tokens=sum(a.response.usage.completion_tokens for a in attempts),
        latency_s=sum(a.response.latency_s for a in attempts),
        # every request the server saw: repairs and transport retries included
        attempts=sum(1 + a.response.retries for a in attempts),
        estimated=any(a.response.usage.estimated for a in attempts),
    )


# -- the factory -----------------------------------------------------------------------------


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


def model_from_settings(settings: Settings, reasoner: str) -> ChatModel:
    """The OpenAI-compatible client of the settings; ReasonerError, naming ``reasoner``, when
    ``ASSISTANTX_LLM_BASE_URL`` is unset or unusable."""
    if not settings.llm_base_url:
        raise ReasonerError(
            f"the {reasoner} reasoner needs ASSISTANTX_LLM_BASE_URL (an OpenAI-compatible /v1 URL)"
        )
    try:
        return OpenAICompatibleModel.from_settings(settings)
    except ValueError as exc:
        raise ReasonerError(f"cannot use the LLM at {settings.llm_base_url}: {exc}") from exc


def build_factory(
    office: Office,
    settings: Settings,
    *,
    model: ChatModel | None = None,
    prompts_dir: str | Path | None = None,
) -> LLMReasonerFactory:
    """The LLM reasoner for ``assistantx.agents.registry`` (``office`` is unused: names resolve
    against each instruction's memory).

    The prompts are loaded and checked now, so a broken template fails at start-up. Without
    ``model`` the OpenAI-compatible client is built from the settings; ReasonerError when
    ``ASSISTANTX_LLM_BASE_URL`` is unset.
    """
    del office  # the resolver comes with each AgentContext
    prompts = AgentPrompts.load(prompts_dir)
    if model is None:
        model = model_from_settings(settings, "llm")
    logger.info("LLM reasoner: %r, output retries %d", model, settings.llm_output_retries)
    return LLMReasonerFactory(
        model,
        prompts,
        output_retries=settings.llm_output_retries,
        budget=focus_budget(settings.llm_context_tokens, settings.llm_max_tokens),
    )


__all__ = [
    "AGENTS",
    "AgentPrompts",
    "LLMReasoner",
    "LLMReasonerFactory",
    "SharedModel",
    "agent_call",
    "build_factory",
    "check_actions",
    "focus_ids",
    "ground_update",
    "ground_updates",
    "schema_text",
]
