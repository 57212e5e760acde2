"""Perception: the focus content for the current step, computed from the memory graph.

The people, items, places and group chats that matter for the frame and for what happened so
far: the requester, every role's candidates and whoever fills them, the items the hand-overs
move, where the robot must go, and the group chats asked. The summary says it in one line.
"""

from __future__ import annotations

from assistantx.agents.symbolic.evidence import Evidence
from assistantx.agents.symbolic.planning import Agenda
from assistantx.agents.symbolic.reading.parser import TaskFrame
from assistantx.agents.symbolic.roles import Roles
from assistantx.core.trace import Percept
from assistantx.memory.graph import LongTermMemory


def perceive(
    frame: TaskFrame, agenda: Agenda | None, ev: Evidence, ltm: LongTermMemory, roles: Roles
) -> Percept:
    people: list[str] = [frame.requester]
    items: list[str] = []
    places: list[str] = [ev.robot_place] if ev.robot_place else []
    groups: list[str] = []
    notes: list[str] = []
    if frame.evidence:
        notes.append(f"read as: {frame.explain()}")
    if frame.decline is not None:
        notes.append(f"nothing to do; to tell {frame.requester}: {frame.decline}")
        return Percept(people=people, places=places, summary="; ".join(notes)[:4000])
    if agenda is None or not frame.understood:
        notes.append(f"unclear request; to ask {frame.requester}: {frame.question}")
        return Percept(people=people, places=places, summary="; ".join(notes)[:4000])
    for view in agenda.tasks:
        for state in view.states.values():
            candidates = roles.candidates(state.role, ltm)
            people += candidates
            if state.person:
                people.append(state.person)
            if state.group:
                groups.append(state.group)
            if state.role.facility:
                places.append(ltm.facility_location(state.role.facility))
            shown = ", ".join(
                f"{p}({ltm.availability(p)}"
                + (f", {state.excluded[p]}" if p in state.excluded else "")
                + ")"
                for p in candidates
            )
            notes.append(
                f"{state.role.key} {state.role.kind}: {state.status}"
                f"{' ' + state.person if state.person else ''} [{shown}]"
            )
        for phase in view.phases:
            items += [i for i, _ in phase.items]
            if phase.place:
                places.append(phase.place)
    locker = ",".join(c.item for c in ev.codes if c.used) or "-"
    notes.append(f"robot at {ev.robot_place}; codes used for {locker}")
    return Percept(
        people=list(dict.fromkeys(people)),
        items=list(dict.fromkeys(items)),
        places=list(dict.fromkeys(places)),
        groups=list(dict.fromkeys(groups)),
        summary="; ".join(notes)[:4000],
    )
