"""What goes into the agents' prompts besides memory: upstream outputs, the previous
reflection, the loop's feedback, what the step did and observed, and each output's shape.

Everything that can carry text from outside (chat messages, the model's own earlier words,
observations) is quoted by the one renderer's ``quote``, so it reads as data, never as orders.
"""

from __future__ import annotations

from collections.abc import Sequence

from pydantic import BaseModel

from assistantx.core.structured import schema_outline
from assistantx.core.trace import ActionResult, Decision, Observation, Plan, Reflection
from assistantx.memory.render import quote
from assistantx.memory.short_term import ShortTermMemory


def schema_text(model: type[BaseModel]) -> str:
    """The shape of a pydantic model's output for a prompt: a compact outline, not the full
    schema. The schema itself goes with the request; the client pastes it into the prompt only
    when the server cannot enforce it, so a prompt never carries it twice (it was 4.7k of
    Decision's 10.2k-character system prompt)."""
    return schema_outline(model)


def json_text(model: BaseModel | None, empty: str) -> str:
    return model.model_dump_json(indent=1) if model is not None else empty


def reflection_text(reflection: Reflection | None) -> str:
    if reflection is None:
        return "(none: this is the first step)"
    return f"verdict {reflection.verdict}: {quote(reflection.reason, 2000)}"


def feedback_text(feedback: Sequence[str]) -> str:
    if not feedback:
        return "(none)"
    # Feedback can echo names the model made up; quote it like any other untrusted text.
    return "\n".join(f"- {quote(line, 1000)}" for line in feedback)


def previous_plan(stm: ShortTermMemory) -> Plan | None:
    """The plan of the last step before this one that had one."""
    for step in reversed(stm.trace.steps[:-1]):
        if step.plan is not None:
            return step.plan
    return None


def actions_text(decision: Decision) -> str:
    return "\n".join(f"- {a.signature()}" for a in decision.actions)


def results_text(results: Sequence[ActionResult]) -> str:
    if not results:
        return "(no action ran)"
    lines = []
    for r in results:
        status = "refused" if r.refused else ("ok" if r.ok else "failed")
        lines.append(f"- {r.action.signature()} -> {status}: {quote(r.observation, 600)}")
    return "\n".join(lines)


def observed_text(observed: Observation) -> str:
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
