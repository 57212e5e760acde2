"""The part of memory an LLM agent sees: what the task touches, not the whole office.

The paper's Perception picks "focus content" from memory; rendering all of memory first makes
that prompt grow with the office (31.6k tokens for 1,024 people). :func:`task_focus` picks
the candidates without a model, from the instruction, the dialogue and the trace:

1. the requester, and everyone the instruction, the dialogue or an action names;
2. for every item type the text mentions (id, name or synonym): the people memory knows to
   own one, those memory believes available first, then those nearest the requester;
3. for every facility the text mentions (or that makes a mentioned product): its guards;
4. the requester's group chats and any group the text names.

:func:`render_focused` renders that focus in the layout of ``memory.render`` with two caps
a prompt budget needs: at most ``max_people`` people (the rest are counted, not listed) and
at most ``max_members`` members per group chat. :func:`focus_budget` turns the context-size
setting into those caps.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from assistantx.core.trace import Percept
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.render import render_short_term
from assistantx.memory.short_term import ShortTermMemory

_WORD = re.compile(r"[a-z0-9_]+")
# Tokens per rendered person row and the fixed part of the largest agent prompt (Decision's
# rules and examples, the percept, the plan, the short-term memory), measured on the default
# office with the SmolLM2 tokenizer and rounded up.
TOKENS_PER_PERSON = 24
FIXED_PROMPT_TOKENS = 2600


@dataclass(frozen=True)
class FocusBudget:
    max_people: int
    max_members: int


def focus_budget(context_tokens: int, max_tokens: int) -> FocusBudget:
    """Caps that keep a prompt plus its answer inside ``context_tokens``."""
    room = context_tokens - max_tokens - FIXED_PROMPT_TOKENS
    people = max(6, min(40, room // TOKENS_PER_PERSON))
    return FocusBudget(max_people=people, max_members=max(6, min(24, people)))


def _words(text: str) -> set[str]:
    return set(_WORD.findall(text.lower().replace("-", " ")))


def _mentions(words: set[str], *names: str) -> bool:
    for name in names:
        parts = _WORD.findall(name.lower().replace("-", " "))
        if parts and all(p in words for p in parts):
            return True
    return False


def task_focus(ltm: LongTermMemory, stm: ShortTermMemory) -> Percept:
    """The people, items, places and groups the instruction and what followed touch."""
    office = ltm.office
    texts = [stm.text, *(t.text for t in stm.dialogue)]
    words = _words(" ".join(texts))
    named: list[str] = [stm.requester]
    for turn in stm.dialogue:
        named.append(turn.person)
    for step in stm.trace.steps:
        for result in step.results:
            named.extend(result.action.targets())
    for person in office.people:
        if person.id in words or _mentions(words, person.name, *person.aliases):
            named.append(person.id)
    items = [
        t.id for t in office.item_types if t.id in words or _mentions(words, t.name, *t.synonyms)
    ]
    facilities = [
        f.id
        for f in office.facilities
        if f.id in words
        or _mentions(words, f.name, *f.synonyms)
        or any(product in items for product in f.products)
    ]
    groups = [g.id for g in office.groups if g.id in words or _mentions(words, g.name)]
    people_ids = {p.id for p in office.people}
    groups += [g for g in ltm.groups_of(stm.requester) if g not in groups]
    owners = _ranked_owners(ltm, stm.requester, items)
    guards = [g for f in facilities for g in ltm.guards(f)]
    people = [p for p in dict.fromkeys([*named, *guards, *owners]) if p in people_ids]
    return Percept(
        people=people,
        items=items,
        places=[*facilities, *(ltm.facility_location(f) for f in facilities)],
        groups=[g for g in dict.fromkeys(groups) if g in {x.id for x in office.groups}],
        summary="",
    )


def _ranked_owners(ltm: LongTermMemory, requester: str, item_types: Iterable[str]) -> list[str]:
    office = ltm.office
    home = office.person(requester).location
    order = {"available": 0, "unknown": 1, "unavailable": 2}
    ranked: list[str] = []
    for item_type in item_types:
        owners = [p for p in ltm.lenders(item_type) if p != requester]
        owners.sort(
            key=lambda p: (
                order[ltm.availability(p)],
                office.distance(home, office.person(p).location),
                p,
            )
        )
        ranked += owners
    return ranked


def merge_focus(model_focus: Percept | None, task: Percept) -> Percept:
    """The model's focus (ids, grounded) first, then the task's; the model's summary."""
    if model_focus is None or not (model_focus.people or model_focus.items):
        return task.model_copy(update={"summary": model_focus.summary if model_focus else ""})
    return Percept(
        people=list(dict.fromkeys([*model_focus.people, *task.people])),
        items=list(dict.fromkeys([*model_focus.items, *task.items])),
        places=list(dict.fromkeys([*model_focus.places, *task.places])),
        groups=list(dict.fromkeys([*model_focus.groups, *task.groups])),
        summary=model_focus.summary,
    )


def render_focused(
    ltm: LongTermMemory, stm: ShortTermMemory, focus: Percept, budget: FocusBudget
) -> str:
    """Memory limited to ``focus`` and ``budget``, in the layout of ``memory.render``."""
    office = ltm.office
    shown = focus.people[: budget.max_people]
    lines = ["PEOPLE (id | name | desk | availability | known items | known to lack):"]
    for person_id in shown:
        person = office.person(person_id)
        items = ",".join(i.split(":")[0] for i in ltm.items_of(person_id)) or "-"
        lacks = ",".join(ltm.known_not_owners_of(person_id)) or "-"
        lines.append(
            f"- {person_id} | {person.name} | {person.location} | "
            f"{ltm.availability(person_id)} | {items} | {lacks}"
        )
    hidden = len(focus.people) - len(shown)
    if hidden > 0:
        lines.append(f"- (and {hidden} more people who may matter; ask a group chat to reach them)")
    places = set(focus.places)
    lines.append("FACILITIES (id | location | guards):")
    for f in office.facilities:
        if not places or f.id in places or f.location in places:
            guards = ltm.guards(f.id)[: budget.max_members]
            lines.append(f"- {f.id} | {f.location} | {','.join(guards) or '-'}")
    lines.append("GROUP CHATS (id | name | members):")
    for g in office.groups:
        if g.id in focus.groups:
            members = ltm.members(g.id)
            listed = ",".join(members[: budget.max_members])
            extra = len(members) - budget.max_members
            more = f",… ({extra} more)" if extra > 0 else ""
            lines.append(f"- {g.id} | {g.name} | {listed}{more}")
    return "\n".join(lines) + "\n" + render_short_term(stm)
