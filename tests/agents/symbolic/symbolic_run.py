"""Running one instruction through the Assistant in the simulated office (a test helper)."""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from dataclasses import dataclass
from typing import Any

from assistantx.agents.symbolic import Task, build_factory
from assistantx.core.events import TraceEvent
from assistantx.core.office import Office
from assistantx.core.ports.messenger import ChatRef
from assistantx.core.settings import Settings
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant
from assistantx.sim.office import SimOffice
from helpers.office import run_one, sim_assistant

EventHook = Callable[[TraceEvent, SimOffice], Awaitable[None]]


@dataclass
class Run:
    stm: ShortTermMemory
    sim: SimOffice
    assistant: Assistant

    @property
    def actions(self) -> list[str]:
        return [r.action.type for r in self.stm.trace.actions() if not r.refused]


async def run_instruction(
    office: Office,
    requester: str,
    text: str,
    *,
    unavailable: tuple[str, ...] = (),
    on_event: EventHook | None = None,
) -> Run:
    sim = SimOffice(office, unavailable=unavailable)
    assistant = sim_assistant(sim, build_factory(office, Settings()))
    if on_event is not None:
        hook = on_event

        async def sink(event: TraceEvent) -> None:
            await hook(event, sim)

        assistant.subscribe(sink)
    stm = await run_one(sim, assistant, requester, text)
    return Run(stm, sim, assistant)


def answer_first_question(
    contact: str, person: str, chat: ChatRef, text: str, asked: list[str]
) -> EventHook:
    """An event hook: the first time the assistant asks ``contact`` something, ``person``
    answers ``text`` in ``chat``; the question is appended to ``asked``."""

    async def answer(event: TraceEvent, sim: SimOffice) -> None:
        result = event.data.get("result")
        if event.kind != "action_result" or not isinstance(result, dict):
            return
        action = result["action"]
        if action["type"] == "inquire" and action["contact"] == contact and not asked:
            asked.append(action["question"])
            sim.messenger.post(person, chat, text, in_reply_to=result["data"]["question_id"])

    return answer


def expected_tasks(case: dict[str, Any], requester: str) -> list[Task]:
    """The frame a case of a YAML understanding set expects (omitted fields: their defaults,
    the recipient the requester)."""
    return [
        Task(
            kind=t["kind"],
            item=t.get("item"),
            owner=t.get("owner"),
            recipient=t.get("recipient", requester),
            actor=t.get("actor"),
            operation=t.get("operation"),
            source=t.get("source"),
        )
        for t in case["tasks"]
    ]
