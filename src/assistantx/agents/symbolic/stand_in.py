"""A named doer who is out: the requester chose them, so another does it only on their yes.

"Can Jo fix my bike tube?" makes Jo the repair bench's doer (``reading.named_doer``): the robot
asks Jo and nobody else. When Jo is away, never answers or says no, the request used to end
unachievable although the bench has a second keeper. The requester named Jo, so switching to
someone else silently would overrule them; giving up would ignore a doer the office has. The
assistant says so and asks: "Jo Bell isn't available. Shall I ask Sam Reid instead?" A yes
opens the doer's role to everyone the office lets do the work (the named one stays excluded by
their own silence or no); a no, or no answer, ends the task as before, saying why.

Who may stand in comes from the office's data only: the other keepers (guards) of the
facility the named keeper runs, or, for a person's work done with a tool (a seal), the other
owners of the tool. A signature is the named person's own: nobody stands in for a signer.
"""

from __future__ import annotations

from dataclasses import replace

from assistantx.agents.symbolic.evidence import Evidence
from assistantx.agents.symbolic.roles import Role, RoleState
from assistantx.core import task_kinds
from assistantx.core.office import Office
from assistantx.memory.graph import LongTermMemory

# The parts of a hand-over that are not the work asked of the named doer.
_NOT_WORK = frozenset({"receive", "lend", "give", "keep", "allow", "send_file"})


def out_doer(actor: str | None, states: dict[str, RoleState]) -> RoleState | None:
    """The state of the role fixed to the request's named doer ``actor`` when it is exhausted
    (they did not answer, said no, are away) and is the only role that is; else None."""
    if actor is None:
        return None
    out = [s for s in states.values() if s.status == "exhausted"]
    if len(out) != 1:
        return None
    role = out[0].role
    if role.fixed != actor or role.kind in _NOT_WORK or actor not in out[0].excluded:
        return None
    return out[0]


def stand_ins(office: Office, role: Role, ltm: LongTermMemory) -> list[str]:
    """Who else the office lets do the role's work: the facility's other keepers, or the tool's
    other owners; nobody for a person's own work (a signature)."""
    if role.facility is not None:
        found = ltm.guards(role.facility)
    elif task_kinds.needs_tool(role.kind):
        tool = task_kinds.tool_type(role.kind, office)
        found = ltm.owners(tool) if tool else []
    else:
        found = []
    return [p for p in dict.fromkeys(found) if p not in (role.fixed, role.requester)]


def question(office: Office, state: RoleState, others: list[str], doing: str) -> str:
    """ "Jo Bell isn't available. Shall I ask Sam Reid instead?" (``doing``: the work, said
    when several could stand in and none is named)."""
    actor = state.role.fixed or ""
    said_no = state.excluded.get(actor) == "said no"
    why = "can't do it" if said_no else "isn't available"
    who = office.person(others[0]).name if len(others) == 1 else f"someone else who can {doing}"
    return f"{office.person(actor).name} {why}. Shall I ask {who} instead?"


def answer(ev: Evidence, text: str) -> str | None:
    """The requester's answer to the stand-in question: "yes", "no" (also any answer that is
    no yes, or silence past the wait: nobody else is asked without a yes), "asked" while
    awaited, None before asking."""
    asked = ev.asked(ev.requester, text)
    if asked is None:
        return None
    if ev.stance_of(asked, ev.requester) == "yes":
        return "yes"
    # a no, an answer that is no yes, or silence past the wait
    return "no" if ev.answers(asked) or ev.expired(asked) else "asked"


def opened(role: Role) -> Role:
    """The role with nobody fixed: any keeper (tool owner) may now do it."""
    return replace(role, fixed=None)
