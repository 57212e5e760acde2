"""The optimal policy: what an agent that knows only the initial memory does, and how long it takes.

The agent knows the spec of the instruction and the long-term memory built from the office
(known ownership, guards, group members), but not who is available: it finds out by asking
(``inquire`` + ``wait``; a timeout means away). It resolves every role before the robot moves
(so an unachievable task costs no driving), then forwards files, then makes its visits and
the final deliveries, sharing a visit when the robot would stop twice at the same person.

**Order of candidates.** For a role with several candidates the agent must choose whom to
ask first without knowing who is away. ``order_candidates`` searches every order and picks
the one with the least expected number of inquiries, then the least worst-case number, then
the least expected driving distance (each candidate away independently with probability
``P_AWAY``), then ids. The number of inquiries does not depend on the order (the expected
count under independent, equal absence and the worst case are the same for every order), so
in effect the search puts the nearest candidate first, as docs/task-semantics.md says; the
search keeps the rule explicit and holds for any other cost model one plugs in.
When every candidate in memory is away the agent asks the largest group chat the requester
belongs to and takes the first helper who answers (asking them again in their own chat when
their own item would leave them: that is where consent is given); nobody answering means
unachievable.

The policy is a generator: it yields a batch of actions and is sent back what it needs to
decide the next batch (who replied, whether the batch succeeded). The same generator runs in
the simulated office (``OptimalReasoner``) and against the truth directly (``dry_run``).
"""

from __future__ import annotations

import itertools
from collections.abc import Generator, Sequence
from dataclasses import dataclass, field
from typing import Literal

from assistantx.agents.oracle.plan import REQUESTER, Code, Role, TaskPlan, Visit, able, candidates
from assistantx.core.actions import (
    Action,
    ForwardFile,
    Inquire,
    Move,
    SendQR,
    Stop,
    Wait,
    WaitInPlace,
)
from assistantx.core.office import Office
from assistantx.core.ports.lock import Purpose
from assistantx.core.task_spec import BaseInstruction
from assistantx.memory.graph import LongTermMemory

P_AWAY = 0.5
ASK_TIMEOUT_S = 60.0
HANDOVER_TIMEOUT_S = 300.0

Resolution = Literal["first", "alternative", "group", "failed"]


@dataclass(frozen=True)
class Feedback:
    """What the last batch showed: who replied, and whether every action succeeded."""

    repliers: tuple[str, ...] = ()
    ok: bool = True


@dataclass
class PolicyLog:
    """How each role was resolved; the generator fills it as it goes."""

    resolutions: dict[str, Resolution] = field(default_factory=dict)
    assigned: dict[str, str] = field(default_factory=dict)
    fell_back: bool = False  # the plan's fallback was used (a colleague's, not the kept one)

    @property
    def level(self) -> Literal["L1", "L2", "L3"]:
        values = set(self.resolutions.values())
        if values & {"group", "failed"}:
            return "L3"
        return "L2" if "alternative" in values else "L1"

    @property
    def achievable(self) -> bool:
        return "failed" not in self.resolutions.values()


Script = Generator[list[Action], Feedback, None]


def meeting_place(office: Office, role: Role, person: str) -> str:
    """Where the robot meets ``person`` for this role (a location id)."""
    if role.kind == "guard" and role.facility is not None:
        return office.facility(role.facility).location
    return office.person(person).location


def order_candidates(
    office: Office, role: Role, people: Sequence[str], start: str, p_away: float = P_AWAY
) -> list[str]:
    """The order to ask candidates in: a search over every order (see the module docstring)."""

    def cost(order: tuple[str, ...]) -> tuple[float, int, float, tuple[str, ...]]:
        expected_asks = 0.0
        expected_m = 0.0
        reach = 1.0  # probability that every earlier candidate was away
        for person in order:
            expected_asks += reach
            distance = office.distance(start, meeting_place(office, role, person))
            desk = office.distance(start, office.person(person).location)
            expected_m += reach * (1 - p_away) * (distance + 1e-3 * desk)
            reach *= p_away
        return (round(expected_asks, 9), len(order), expected_m, order)

    if len(people) > 7:  # 8! orders is still fine, more is not: fall back to the greedy rule
        return sorted(people, key=lambda p: (office.distance(start, office.person(p).location), p))
    best = min(itertools.permutations(people), key=cost, default=())
    return list(best)


# A visit is one decision: its codes and the wait for the hand-over (Decision holds at most 4).
MAX_CODES_PER_VISIT = 3


def runs_it_alone(office: Office, role: Role, requester: str) -> bool:
    """Whether ``role`` is a guard's whose facility only the requester runs."""
    if role.kind != "guard" or role.facility is None:
        return False
    return set(office.facility(role.facility).guards) == {requester}


def biggest_group(office: Office, person: str) -> str | None:
    groups = [g for g in office.groups if person in g.members]
    if not groups:
        return None
    return max(groups, key=lambda g: (len(g.members), g.id)).id


def optimal_script(
    base: BaseInstruction, plan: TaskPlan, office: Office, ltm: LongTermMemory, log: PolicyLog
) -> Script:
    a = base.requester
    home = office.robot.home
    names = {p.id: p.name for p in office.people}

    # 1. resolve every role by asking
    for role in plan.roles:
        if role.key in log.assigned:
            continue  # found before falling back to this plan
        if runs_it_alone(office, role, a):
            # the requester is the only one who runs the facility: they do it themselves with
            # the robot (their request is their yes), nobody is asked
            log.assigned[role.key] = a
            log.resolutions[role.key] = "first"
            continue
        tried: list[str] = []
        for person in order_candidates(office, role, candidates(role, ltm, a), home):
            tried.append(person)
            feedback = yield [
                Inquire(contact=person, question=role.question),
                Wait(reason=f"waiting for {person}'s answer", timeout_s=ASK_TIMEOUT_S),
            ]
            if person in feedback.repliers:
                log.assigned[role.key] = person
                log.resolutions[role.key] = "first" if len(tried) == 1 else "alternative"
                break
        if role.key in log.assigned:
            continue
        group = biggest_group(office, a)
        if role.group_question is not None and group is not None:
            feedback = yield [
                Inquire(contact=group, question=role.group_question),
                Wait(reason=f"waiting for an answer in {group}", timeout_s=ASK_TIMEOUT_S),
            ]
            # a guard's job is done by a guard: someone offering their own item instead ("I
            # have a label maker" to "could anyone take it out of the cupboard?") is no yes
            helpers = [
                p
                for p in feedback.repliers
                if p != a and p not in tried and (role.kind != "guard" or able(role, office, p))
            ]
            for helper in helpers[: 1 if not role.own_item_leaves else None]:
                if role.own_item_leaves:  # a yes in the group: the owner's own yes in their chat
                    feedback = yield [
                        Inquire(contact=helper, question=role.question),
                        Wait(reason=f"waiting for {helper}'s answer", timeout_s=ASK_TIMEOUT_S),
                    ]
                    if helper not in feedback.repliers:
                        continue
                log.assigned[role.key] = helper
                log.resolutions[role.key] = "group"
                break
            if role.key in log.assigned:
                continue
        if plan.fallback is not None and all(r.key != role.key for r in plan.fallback.roles):
            # the kept one cannot be had (its keeper is away): borrow a colleague's instead
            log.resolutions[role.key] = "alternative"
            log.fell_back = True
            yield from optimal_script(base, plan.fallback, office, ltm, log)
            return
        log.resolutions[role.key] = "failed"
        asked = ", ".join(names[p] for p in tried) or "nobody in memory"
        yield [
            Stop(
                outcome="unachievable",
                summary=f"I could not do this: {asked} did not answer and nobody else could "
                "help, so nothing was done.",
            )
        ]
        return

    def who(ref: str) -> str:
        if ref == REQUESTER:
            return a
        return log.assigned.get(ref, ref)

    def item_of(code: Code) -> str:
        item = code.item
        for key, person in log.assigned.items():
            item = item.replace("{" + key + "}", person)
        return item

    # 2. files: each to each person once. The requester runs the printer: it is their file;
    # the keeper who prints it is the one it is also to be sent to: one forward serves both
    # (a second one would only repeat the first)
    # (a file named only where it is not the source's own: the one kind of several the work
    # takes, "audio:ines" for the CD burner)
    pairs: list[tuple[str, str, str | None]] = []
    for f in plan.forwards:
        source = who(f.source)
        file = None if f.file in (None, office.file_of(source)) else f.file
        pair = (source, who(f.target), file)
        if pair[0] != pair[1] and pair not in pairs:
            pairs.append(pair)
    forwards: list[Action] = [ForwardFile(source=s, target=t, file=file) for s, t, file in pairs]
    if forwards:
        feedback = yield forwards
        if not feedback.ok:
            yield [Stop(outcome="failed", summary="A file could not be forwarded.")]
            return

    # 3. visits, then the final deliveries (one visit per recipient), sharing stops
    visits = list(plan.visits)
    recipients: list[str] = []
    for recipient, _ in plan.deliveries:
        if recipient not in recipients:
            recipients.append(recipient)
    for recipient in recipients:
        codes = tuple(c for r, c in plan.deliveries if r == recipient)
        visits.append(Visit(recipient, recipient, codes))
    merged: list[Visit] = []
    for visit in visits:
        last = merged[-1] if merged else None
        if last is not None and (who(last.place), who(last.person)) == (
            who(visit.place),
            who(visit.person),
        ):
            merged[-1] = Visit(last.place, last.person, last.codes + visit.codes)
        elif (
            last is not None
            and who(last.person) == who(visit.person) == a
            and REQUESTER in (last.place, visit.place)
            and len(last.codes) + len(visit.codes) <= MAX_CODES_PER_VISIT
        ):
            # the requester runs the facility themselves: everything of theirs is handed over
            # where they work it, not at their desk before and after
            place = visit.place if last.place == REQUESTER else last.place
            merged[-1] = Visit(place, last.person, last.codes + visit.codes)
        else:
            merged.append(visit)

    robot_at = home
    for visit in merged:
        person = who(visit.person)
        place = who(visit.place)
        location = (
            office.facility(place).location
            if any(f.id == place for f in office.facilities)
            else office.person(place).location
        )
        if location != robot_at:
            # The move is a step of its own: late answers from a group chat that arrive while
            # driving are taken in at the next step, so they do not cut the hand-over wait short.
            feedback = yield [Move(place=place)]
            if not feedback.ok:
                yield [Stop(outcome="failed", summary=f"The robot could not reach {place}.")]
                return
            robot_at = location
        batch: list[Action] = []
        for code in visit.codes:
            purpose: Purpose = code.purpose
            batch.append(
                SendQR(
                    contact=person,
                    item=item_of(code),
                    purpose=purpose,
                    operation=code.operation,
                    destination=code.destination,
                    send_to=code.send_to,
                )
            )
        batch.append(WaitInPlace(person=person, timeout_s=HANDOVER_TIMEOUT_S))
        feedback = yield batch
        if not feedback.ok:
            yield [Stop(outcome="failed", summary=f"The hand-over with {names[person]} failed.")]
            return
    yield [Stop(outcome="done", summary=f"Done: {base.text}")]


@dataclass
class DryRun:
    actions: list[Action]
    log: PolicyLog

    @property
    def outcome(self) -> str:
        last = self.actions[-1]
        return last.outcome if isinstance(last, Stop) else "failed"


def dry_run(
    base: BaseInstruction,
    plan: TaskPlan,
    office: Office,
    unavailable: set[str],
    ltm: LongTermMemory | None = None,
) -> DryRun:
    """Play the policy against the truth without the simulator (for classifying variants).

    Asked people reply when available; in a group, the available members able to fill the
    role: the first of them in member order answers, as the simulated people do.
    """
    ltm = ltm or LongTermMemory(office)
    log = PolicyLog()
    script = optimal_script(base, plan, office, ltm, log)
    actions: list[Action] = []
    batch = next(script)
    while True:
        actions.extend(batch)
        feedback = _oracle(batch, plan, office, unavailable, base.requester)
        try:
            batch = script.send(feedback)
        except StopIteration:
            break
    return DryRun(actions, log)


def _oracle(
    batch: list[Action], plan: TaskPlan, office: Office, unavailable: set[str], requester: str
) -> Feedback:
    """Who answers: the asked person when available; in a group, the first available member
    able to fill the role (the others see the offer and stay quiet, as in the simulator)."""
    asks = [x for x in batch if isinstance(x, Inquire)]
    if not asks:
        return Feedback()
    contact = asks[0].contact
    if any(g.id == contact for g in office.groups):
        roles = [*plan.roles, *(plan.fallback.roles if plan.fallback else ())]
        role = next(r for r in roles if r.group_question == asks[0].question)
        members = office.group(contact).members
        helpers = [
            p for p in members if p not in unavailable and p != requester and able(role, office, p)
        ]
        return Feedback(tuple(helpers[:1]), ok=True)
    if contact in unavailable:
        return Feedback((), ok=False)
    return Feedback((contact,))
