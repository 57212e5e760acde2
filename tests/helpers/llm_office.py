"""Running instructions with the LLM agents in the simulated office, the model being the
scripted OpenAI-compatible server over real HTTP.

The fake model's "reasoning" for Perception, Planning and Reflection is a few rules applied
to the prompt the agents rendered (the results and the observed changes); Decision is
scripted per test, as a queue of answers or as callables that read the prompt.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from assistantx.adapters.model import model_from_settings
from assistantx.agents.llm import LLMReasonerFactory, build_factory
from assistantx.core.actions import Action
from assistantx.core.office import Office
from assistantx.core.ports.model import ChatModel
from assistantx.core.settings import Settings
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from fakes.scripted_llm import RecordedRequest, ScriptedLLM
from helpers.office import run_one, sim_assistant

GROUPS = ("office_work", "study_group")
# The actions of a fetch the scripted helpers play to the end: ask, then fetch and hand over.
CANONICAL_FETCH = [
    "inquire",
    "wait",
    "move",
    "send_qr",
    "wait_in_place",
    "move",
    "send_qr",
    "wait_in_place",
    "stop",
]

# "- inquire(contact='zhang', question='…') -> ok: …" as the reflection prompt lists results
_RESULT = re.compile(r"^- (?P<type>\w+)\((?P<args>.*)\) -> (?P<status>ok|failed|refused): ", re.M)
_CONTACT = re.compile(r"contact='(?P<contact>[^']+)'")
_MESSAGE = re.compile(r'^new message: (?P<person>\w+) in (?P<chat>\w+): "(?P<text>[^"]*)', re.M)
_OFFER = re.compile(r"^(?:Yes, )?I have an? (?P<item>[a-z ]+?)[,.]")


def section(text: str, title: str) -> str:
    """The body under ``TITLE:`` in a rendered prompt, up to the next blank line."""
    head = f"{title}:\n"
    start = (0 if text.startswith(head) else text.index(f"\n{head}") + 1) + len(head)
    end = text.find("\n\n", start)
    return text[start : end if end >= 0 else len(text)]


def perception(request: RecordedRequest) -> dict[str, Any]:
    """No particular focus: later agents then see the whole of memory."""
    return {"summary": "scripted percept: everything in memory may matter"}


def planning(request: RecordedRequest) -> dict[str, Any]:
    return {"goal": "carry out the instruction", "subgoals": [{"description": "do it"}]}


def reflection(request: RecordedRequest) -> dict[str, Any]:
    """Y when every action went well; marks people who stayed silent unavailable, people who
    wrote available, and people who offered an item in a group chat as its owners."""
    text = request.last_user_text
    results = list(_RESULT.finditer(section(text, "RESULTS")))
    updates: list[dict[str, Any]] = []
    asked = [
        m.group("contact")
        for r in results
        if r.group("type") == "inquire"
        for m in [_CONTACT.search(r.group("args"))]
        if m
    ]
    timed_out = any(r.group("type") == "wait" and r.group("status") == "failed" for r in results)
    if timed_out:
        for person in asked:
            if person not in GROUPS:
                updates.append(
                    {
                        "kind": "availability",
                        "person": person,
                        "available": False,
                        "evidence": f"no reply from {person} before the wait timed out",
                    }
                )
    for message in _MESSAGE.finditer(section(text, "CHANGES OBSERVED DURING THE STEP")):
        person, chat, said = message.group("person", "chat", "text")
        updates.append(
            {
                "kind": "availability",
                "person": person,
                "available": True,
                "evidence": f"{person} wrote in {chat}",
            }
        )
        offer = _OFFER.match(said)
        if offer and chat in GROUPS:
            updates.append(
                {
                    "kind": "ownership",
                    "person": person,
                    "item_type": offer.group("item"),
                    "owns": True,
                    "evidence": f"{person} in {chat}: {said}",
                }
            )
    failed = [r for r in results if r.group("status") != "ok"]
    return {
        "verdict": "N" if failed else "Y",
        "reason": "something did not work" if failed else "the step went as planned",
        "updates": updates,
    }


def decision(*actions: Action | dict[str, Any], thought: str = "scripted") -> dict[str, Any]:
    return {
        "thought": thought,
        "actions": [a if isinstance(a, dict) else a.model_dump(mode="json") for a in actions],
    }


def people_rows(prompt: str) -> dict[str, list[str]]:
    """person id → [name, desk, availability, known items, known to lack], from the prompt."""
    rows = {}
    for line in section(prompt, "MEMORY").splitlines():
        if line.startswith("- ") and line.count(" | ") == 5:
            cells = line[2:].split(" | ")
            rows[cells[0]] = cells[1:]
    return rows


def script_helpers(llm: ScriptedLLM) -> None:
    """Perception, Planning and Reflection answered by the rules above."""
    llm.respond_with(perception, "perception")
    llm.respond_with(planning, "planning")
    llm.respond_with(reflection, "reflection")


def llm_settings(llm: ScriptedLLM, **overrides: Any) -> Settings:
    values: dict[str, Any] = {
        "llm_base_url": llm.base_url,
        "llm_model": "scripted-model",
        "llm_timeout_s": 5.0,
        "llm_max_retries": 4,
        "llm_output_retries": 2,
    }
    values.update(overrides)
    return Settings(**values)


def llm_model(llm: ScriptedLLM, **overrides: Any) -> ChatModel:
    """The client of ``llm`` as the composition root builds it from the settings."""
    model = model_from_settings(llm_settings(llm, **overrides))
    assert model is not None
    return model


@dataclass
class LLMRun:
    stm: ShortTermMemory
    sim: SimOffice
    assistant: Assistant
    factory: LLMReasonerFactory

    def action_types(self) -> list[str]:
        return [r.action.type for r in self.stm.trace.actions() if not r.refused]


def make_assistant(
    office: Office,
    sim: SimOffice,
    factory: LLMReasonerFactory,
    *,
    max_steps: int = 20,
) -> Assistant:
    return sim_assistant(sim, factory, reasoner_name="llm", limits=LoopLimits(max_steps=max_steps))


async def run_llm(
    office: Office,
    llm: ScriptedLLM,
    text: str,
    *,
    requester: str = "lee",
    unavailable: tuple[str, ...] = (),
    max_steps: int = 20,
    **settings: Any,
) -> LLMRun:
    """One instruction, start to end, with the LLM reasoner talking to ``llm``."""
    sim = SimOffice(office, unavailable=unavailable)
    factory = build_factory(office, llm_settings(llm, **settings), model=llm_model(llm, **settings))
    assistant = make_assistant(office, sim, factory, max_steps=max_steps)
    stm = await run_one(sim, assistant, requester, text)
    return LLMRun(stm, sim, assistant, factory)
