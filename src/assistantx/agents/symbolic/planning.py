"""Planning: a task frame split into ordered sub-goals, with the progress read from memory.

Each task compiles to roles (who lends, prints, signs, receives) and phases, following the
canonical sequences of docs/task-semantics.md:

- ``Confirm(role)``: find someone for the role (ask, wait, next candidate, group chat);
- ``Forward``: pass an electronic file on;
- ``Handover(role, legs)``: the robot goes to the person, who uses one-time codes for each leg
  (deposit, collect, sign, seal, copy, heat, produce).

Progress is recomputed at every step from the evidence (codes used, files forwarded, answers),
so a deviation (a refusal, a timeout, a person who did not come) re-plans by itself: the role
loses its person and its Confirm phase is unmet again.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

from assistantx.agents.symbolic import stand_in
from assistantx.agents.symbolic.evidence import Evidence
from assistantx.agents.symbolic.plan_parts import left_out, moves_nothing
from assistantx.agents.symbolic.roles import Role, RoleKind, Roles, RoleState
from assistantx.core import task_kinds
from assistantx.core.english import wording
from assistantx.core.office import Office
from assistantx.core.ports.lock import Purpose
from assistantx.core.task_schema import Task, TaskFrame, kind_shape, operation_of
from assistantx.core.trace import Plan, SubGoal
from assistantx.core.wording import (
    a_thing,
    file_noun,
    item_phrase,
    item_type_name,
    operation_verb,
    person_name,
    product_words,
    purpose_text,
)
from assistantx.memory.graph import LongTermMemory

TaskStatus = Literal["done", "active", "unachievable", "failed"]


@dataclass(frozen=True)
class Leg:
    item_type: str
    owner_fixed: str | None  # the item's owner when the frame fixes it
    owner_role: str | None  # else: whoever fills this role (any owner's stapler)
    purpose: Purpose


@dataclass(frozen=True)
class Confirm:
    role: Role


@dataclass(frozen=True)
class Forward:
    source: str
    target_role: Role
    file: str


@dataclass(frozen=True)
class Handover:
    role: Role
    legs: tuple[Leg, ...]


Phase = Confirm | Forward | Handover


@dataclass
class CompiledTask:
    task: Task
    roles: list[Role]
    phases: list[Phase]


@dataclass
class PhaseView:
    phase: Phase
    done: bool
    description: str
    person: str | None = None
    place: str | None = None
    items: list[tuple[str, Purpose]] = field(default_factory=list)
    pending: list[tuple[str, Purpose]] = field(default_factory=list)  # items' codes still to use


@dataclass
class TaskView:
    compiled: CompiledTask
    states: dict[str, RoleState]
    phases: list[PhaseView]
    status: TaskStatus
    reason: str = ""
    # a question for the requester before the task goes on (a named doer is out: "Shall I ask
    # Sam Reid instead?", ``stand_in``)
    ask: str | None = None

    @property
    def current(self) -> PhaseView | None:
        return next((p for p in self.phases if not p.done), None)


@dataclass
class Agenda:
    frame: TaskFrame
    tasks: list[TaskView]

    @property
    def active(self) -> TaskView | None:
        return next((t for t in self.tasks if t.status == "active"), None)


class Planner:
    def __init__(self, office: Office, roles: Roles) -> None:
        self.office = office
        self.roles = roles

    # -- compiling -----------------------------------------------------------------------
    def compile(self, frame: TaskFrame) -> list[CompiledTask]:
        return [self._compile(n, t, frame.requester) for n, t in enumerate(frame.tasks)]

    def _facility_for(self, t: Task) -> str:
        """The facility that offers the task's operation: one its named doer keeps ("could
        Mao print my file?"), else the first that does."""
        op = operation_of(self.office, t)
        offering = self.office.offering(op) if op else []
        if not offering:
            raise LookupError(f"no facility for {t.kind} {t.item}")
        kept = [f for f in offering if t.actor is not None and t.actor in f.guards]
        return (kept or offering)[0].id

    def _runner(self, t: Task, requester: str) -> str | None:
        """Who runs the facility for the task: the keeper the request named ("could Mao print
        my file?", ``reading.named_doer``), or the requester who is its only keeper, or any
        keeper (None). A named doer who keeps none of them is no runner."""
        guards = self.office.facility(self._facility_for(t)).guards
        if t.actor is not None and t.actor in guards:
            return t.actor
        return self._runs_alone(t, requester)

    def _runs_alone(self, t: Task, requester: str) -> str | None:
        """The requester, when they are the only guard of the facility the task needs: they
        run it themselves with the robot (nobody else can be asked; the oracle's
        ``policy.runs_it_alone`` plans the same)."""
        guards = self.office.facility(self._facility_for(t)).guards
        return requester if set(guards) == {requester} else None

    def _source(self, n: int, t: Task, requester: str, held: frozenset[str] = frozenset()) -> Role:
        """Who puts the item into the locker (``held``: items an earlier task of the request
        brought to the requester: they have them now, wherever they are kept)."""
        item_type = t.item or ""
        if (
            t.source is not None
            and t.source != t.owner
            and t.source in {p.id for p in self.office.people}
        ):
            # "P lent me her ruler, please return it to her; it's on my desk": whoever the
            # request says has it puts it in, not the owner the office file names
            return Role(
                f"{n}.source",
                "give",
                requester,
                fixed=t.source,
                item_type=item_type,
                item_owner=t.owner,
                beneficiary=t.recipient,
            )
        if t.owner is not None and f"{item_type}:{t.owner}" in held:
            # "get my lunch out of the fridge and heat it", read as two tasks: the lunch is
            # with them now, so they put it in; the fridge's keeper is not asked again
            return Role(
                f"{n}.source",
                "give",
                requester,
                fixed=requester,
                item_type=item_type,
                item_owner=t.owner,
                beneficiary=t.recipient,
            )
        kept = self.office.keeper(t.owner, item_type) if t.owner else None
        if kept is not None:
            return Role(
                f"{n}.source",
                "keep",
                requester,
                # the requester who alone keeps it takes it out themselves (their request is
                # their yes), as the oracle plans it (``policy.runs_it_alone``); with a fellow
                # keeper, that keeper is asked, never the requester instead
                fixed=requester if set(kept.guards) == {requester} else None,
                item_type=item_type,
                item_owner=t.owner,
                facility=kept.id,
            )
        if t.owner is None:
            return Role(
                f"{n}.source", "lend", requester, item_type=item_type, beneficiary=t.recipient
            )
        kind: RoleKind = "lend" if self.office.item_type(item_type).kind == "belonging" else "give"
        return Role(
            f"{n}.source",
            kind,
            requester,
            fixed=t.owner,
            item_type=item_type,
            item_owner=t.owner,
            beneficiary=t.recipient,
        )

    def _consent(self, n: int, t: Task, requester: str) -> list[Role]:
        """The owner's own yes for their item that a keeper takes out (Joy's yoghurt from the
        fridge): the keeper cannot give it away for them (runtime/consent.py)."""
        if t.owner is None or t.owner == requester or t.item is None:
            return []
        if self.office.is_supply(f"{t.item}:{t.owner}"):
            return []  # owned by nobody (the stationery cupboard's pens): no one's yes
        kept = self.office.keeper(t.owner, t.item)
        if kept is None:
            return []
        return [
            Role(
                f"{n}.owner",
                "allow",
                requester,
                fixed=t.owner,
                item_type=t.item,
                item_owner=t.owner,
                facility=kept.id,
                beneficiary=t.recipient,
            )
        ]

    def _compile(
        self,
        n: int,
        t: Task,
        requester: str,
        *,
        kept: bool = True,
        held: frozenset[str] = frozenset(),
    ) -> CompiledTask:
        """``kept``: whether a transfer that names nobody's item uses the one kept at a
        facility; without it (the keeper is away), any colleague's at hand is borrowed."""
        if t.kind == "transfer" and t.owner is None and t.item and kept:
            # nobody's named: the one kept at a facility (the cupboard's label maker, its
            # supply of tape) first, as the oracle does (agents/oracle/plan.py)
            keeper = self.office.kept_owner(t.item, besides=requester)
            t = t.model_copy(update={"owner": keeper}) if keeper else t
        recipient = Role(f"{n}.recipient", "receive", requester, fixed=t.recipient)
        if t.source is not None and t.owner == t.recipient and t.source != t.owner:
            # given back: the owner is asked about their own item by name, so their yes is
            # also the owner's yes the locker's guard wants before it leaves the borrower
            recipient = Role(
                f"{n}.recipient",
                "receive",
                requester,
                fixed=t.recipient,
                item_type=t.item,
                item_owner=t.owner,
            )
        phases: list[Phase] = []
        roles: list[Role] = []

        def leg(
            item_type: str, purpose: Purpose, owner: str | None = None, role: Role | None = None
        ) -> Leg:
            return Leg(item_type, owner, role.key if role else None, purpose)

        owner = t.owner or requester
        item = t.item or ""
        op = operation_of(self.office, t)
        product = (self.office.operation(op).product if op else None) or item
        source_type = (self.office.operation(op).input if op else None) or item
        match t.kind:
            case "transfer":
                source = self._source(n, t, requester, held)
                roles = [source, recipient]
                it = leg(item, "deposit", t.owner, None if t.owner else source)
                out = Leg(it.item_type, it.owner_fixed, it.owner_role, "collect")
                phases = [Handover(source, (it,)), Handover(recipient, (out,))]
                if source.kind == "keep" and source.fixed == requester == t.recipient:
                    # the requester takes it out of the facility they keep and takes it from
                    # the robot there: both codes at one stop, as the oracle hands them
                    roles, phases = [source], [Handover(source, (it, out))]
            case "print":
                guard = Role(
                    f"{n}.renderer",
                    "print",
                    requester,
                    fixed=self._runner(t, requester),
                    item_type=source_type,
                    item_owner=owner,
                    facility=self._facility_for(t),
                    operation=op,
                )
                roles = [guard, recipient]
                if owner != requester:
                    roles.append(
                        Role(
                            f"{n}.file",
                            "send_file",
                            requester,
                            fixed=owner,
                            item_type=source_type,
                            beneficiary=requester,
                        )
                    )
                # a requester who runs the printer alone has their own file already
                send: list[Phase] = (
                    []
                    if guard.fixed == owner
                    else [Forward(owner, guard, f"{source_type}:{owner}")]
                )
                phases = [
                    *send,
                    Handover(guard, (leg(product, "produce", owner),)),
                    Handover(recipient, (leg(product, "collect", owner),)),
                ]
            case "copy":
                source = self._source(n, t, requester, held)
                by_message = self.office.item_type(product).electronic
                guard = Role(
                    f"{n}.copier",
                    "copy",
                    requester,
                    fixed=self._runner(t, requester),
                    item_type=item,
                    item_owner=owner,
                    facility=self._facility_for(t),
                    operation=op,
                    # a scan to PDF for someone else: the operator sends it to them, told by
                    # name in the code's message, as nobody carries it to them
                    send_to=t.recipient if by_message and t.recipient not in ("", owner) else None,
                )
                # the original comes back to whoever put it in, unless a facility's keeper
                # took it out (a film from the picture archive): then to its owner, who asked
                # or agreed, as the oracle plans it; a keeper is no recipient
                home = source
                if source.kind == "keep":
                    home = (
                        recipient
                        if t.recipient == owner
                        else Role(f"{n}.back", "receive", requester, fixed=owner)
                    )
                roles = [guard, source, *([home] if home not in (source, recipient) else [])]
                roles.append(recipient)
                back: list[Phase]
                if by_message:
                    # scanned to PDF: the operator sends the file by message to the recipient
                    # (``send_to``); only the original comes back
                    roles = [r for r in roles if r is not recipient or r is home]
                    back = [Handover(home, (leg(item, "collect", owner),))]
                elif t.recipient == owner:
                    back = [
                        Handover(
                            home, (leg(item, "collect", owner), leg(product, "collect", owner))
                        )
                    ]
                else:
                    back = [
                        Handover(home, (leg(item, "collect", owner),)),
                        Handover(recipient, (leg(product, "collect", owner),)),
                    ]
                phases = [
                    Handover(source, (leg(item, "deposit", owner),)),
                    Handover(guard, (leg(item, "copy", owner),)),
                    *back,
                ]
            case "produce":
                guard = Role(
                    f"{n}.maker",
                    "produce",
                    requester,
                    # "can Gao knock one up?": the keeper asked to make it, when the reader
                    # named one (it names only a keeper of a facility that makes it)
                    fixed=t.actor or self._runs_alone(t, requester),
                    item_type=item,
                    facility=self._facility_for(t),
                    operation=op,
                    beneficiary=t.recipient,
                )
                roles = [guard, recipient]
                phases = [
                    Handover(guard, (leg(item, "produce", t.recipient),)),
                    Handover(recipient, (leg(item, "collect", t.recipient),)),
                ]
            case kind if task_kinds.works_on_item(kind):
                # The work-on-the-item kinds of the table (sign, seal, heat ...): the item
                # goes in, the doer works on it, the recipient takes it out.
                spec = task_kinds.kind(kind)
                source = self._source(n, t, requester, held)
                doer = Role(
                    f"{n}.{spec.doer}",
                    kind,
                    requester,
                    fixed=t.actor if spec.by_person else self._runner(t, requester),
                    item_type=item,
                    item_owner=owner,
                    facility=None if spec.by_person else self._facility_for(t),
                    operation=None if spec.by_person else op,
                    destination=t.destination
                    if op is not None and self.office.operation(op).sends_out
                    else None,
                )
                party = {"source": source, "doer": doer, "recipient": recipient}
                steps = spec.steps
                if op is not None and not self.office.operation(op).returns_item:
                    # a shredded or faxed-out document does not come back: nobody collects it
                    steps = tuple(s for s in steps if s.party != "recipient")
                # A person who does the work is sought first (a signer may be away); a
                # facility's guard is found where the facility is.
                roles = [doer, source, recipient] if spec.by_person else [source, doer, recipient]
                if len(steps) < len(spec.steps):
                    roles.remove(recipient)
                phases = [
                    Handover(party[step.party], (leg(item, step.purpose, owner),)) for step in steps
                ]
            case "send_file":
                if owner != requester:
                    roles = [
                        Role(
                            f"{n}.file",
                            "send_file",
                            requester,
                            fixed=owner,
                            item_type=item,
                            beneficiary=t.recipient,
                        )
                    ]
                phases = [Forward(owner, recipient, self.office.file_of(owner, item))]
        roles = [*self._consent(n, t, requester), *roles]
        confirms: list[Phase] = [Confirm(r) for r in roles if r.confirm]
        return CompiledTask(t, roles, [*confirms, *phases])

    # -- progress ------------------------------------------------------------------------
    def agenda(self, frame: TaskFrame, ltm: LongTermMemory, ev: Evidence, now: float) -> Agenda:
        views: list[TaskView] = []
        # items an earlier task brought (or brought back) to the requester, with the code
        # that did: a later task on the same item starts from them and counts only codes
        # used after that
        after: dict[str, int] = {}
        # items an earlier task on them could not finish (a signature nobody could give):
        # the request's later tasks on the same item wait on it ("get my drawings signed,
        # then courier them" sends no unsigned drawings out)
        blocked: dict[str, str] = {}
        requester = frame.requester
        whole = [self._compile(n, t, requester) for n, t in enumerate(frame.tasks)]
        missing = left_out(self.office, whole) or moves_nothing(whole)
        if missing is not None:  # a part left out: nothing moves, the reason says which
            return Agenda(frame, [TaskView(c, {}, [], "unachievable", missing) for c in whole])
        for n, task in enumerate(frame.tasks):
            held = frozenset(after)
            compiled = self._compile(n, task, requester, held=held)
            view = self._view(compiled, ltm, ev, now, after)
            if view.status == "unachievable" and task.owner is None and compiled.task.owner:
                # the kept one cannot be had (its keeper is away, none is left): borrow one
                # from a colleague instead, with their own yes, as the oracle does
                other = self._view(
                    self._compile(n, task, requester, kept=False, held=held), ltm, ev, now, after
                )
                view = other if other.status != "unachievable" else view
            view = self._stand_in(view, ltm, ev, now, after)
            item = self._item_in_hand(view.compiled.task, requester)
            if item in blocked and view.status == "active" and not _moved(view):
                view.status = "unachievable"
                view.reason = f"it was to follow: {blocked[item]}"
            if item is not None and view.status in ("unachievable", "failed"):
                blocked.setdefault(item, describe(view.compiled.task, self.office, requester))
            views.append(view)
            # any finished task that handed the item back (a fetch, a copy, a binding): a
            # later task on it ("photocopy and bind my plan") starts with the requester
            # holding it, and its own hand-overs are the codes used after that
            if view.status == "done":
                for item, _ in (i for p in view.phases for i in p.items if i[1] == "collect"):
                    found = _first_used(ev, item, "collect", requester, after.get(item, -1))
                    if found is not None and compiled.task.recipient == requester:
                        after[item] = found
        return Agenda(frame, views)

    def _item_in_hand(self, t: Task, requester: str) -> str | None:
        """The physical item a task hands around (the requester's drawing set to sign, their
        film to develop, a named owner's stapler); None for a product, a file or anyone's."""
        if t.item is None or t.kind == "produce" or not self.office.item_type(t.item).physical:
            return None
        owner = t.owner or (None if t.kind == "transfer" else requester)
        return f"{t.item}:{owner}" if owner else None

    def _view(
        self,
        compiled: CompiledTask,
        ltm: LongTermMemory,
        ev: Evidence,
        now: float,
        after: dict[str, int] | None = None,
    ) -> TaskView:
        states: dict[str, RoleState] = {}
        for role in compiled.roles:
            states[role.key] = self.roles.resolve(role, ltm, ev, now)
        phases: list[PhaseView] = []
        for phase in compiled.phases:
            phases.append(self._phase(phase, states, ltm, ev, after or {}))
        # a Confirm is also done once every phase using its role is done
        for k, view in enumerate(phases):
            if isinstance(view.phase, Confirm) and not view.done:
                key = view.phase.role.key
                users = [p for p in phases[k + 1 :] if _uses(p.phase, key)]
                view.done = bool(users) and all(p.done for p in users)
        status: TaskStatus = "done" if all(p.done for p in phases) else "active"
        reason = ""
        if status == "active":
            pending_keys = {_role_key(p.phase) for p in phases if not p.done} - {None}
            pending_keys |= {
                leg.owner_role
                for p in phases
                if not p.done and isinstance(p.phase, Handover)
                for leg in p.phase.legs
                if leg.owner_role
            }
            out = [
                states[k] for k in pending_keys if k in states and states[k].status == "exhausted"
            ]
            if out:
                moved = any(p.done and isinstance(p.phase, Handover) for p in phases)
                status = "failed" if moved else "unachievable"
                reason = "; ".join(self._why(s) for s in out)
        return TaskView(compiled, states, phases, status, reason)

    def _stand_in(
        self,
        view: TaskView,
        ltm: LongTermMemory,
        ev: Evidence,
        now: float,
        after: dict[str, int],
    ) -> TaskView:
        """A task whose named doer is out (``stand_in``): on the requester's yes, the same task
        with the doer's role open to the others the office lets do it (also once done, so the
        outcome thanks whoever stood in); before their answer, the task waits on the question;
        on a no, it ends as it was, saying so."""
        if view.status == "active":
            return view
        out = stand_in.out_doer(view.compiled.task.actor, view.states)
        if out is None:
            return view
        others = stand_in.stand_ins(self.office, out.role, ltm)
        if not others:
            return view  # nobody else may do it (a signature): ends as before
        text = stand_in.question(self.office, out, others, role_text(out.role, self.office))
        said = stand_in.answer(ev, text)
        if said == "yes":
            compiled = _with_role(view.compiled, out.role, stand_in.opened(out.role))
            return self._view(compiled, ltm, ev, now, after)
        if view.status == "done":
            return view
        if said == "no":
            view.reason = f"{view.reason}; you did not want anyone else asked"
            return view
        view.status, view.ask = "active", text
        return view

    def _phase(
        self,
        phase: Phase,
        states: dict[str, RoleState],
        ltm: LongTermMemory,
        ev: Evidence,
        after: dict[str, int],
    ) -> PhaseView:
        if isinstance(phase, Confirm):
            state = states[phase.role.key]
            return PhaseView(
                phase,
                state.bound,
                f"find who can {role_text(phase.role, self.office)}",
                person=state.person,
            )
        if isinstance(phase, Forward):
            target = states.get(phase.target_role.key)
            person = target.person if target and target.bound else phase.target_role.fixed
            done = any(
                s == phase.source and f == phase.file and (person is None or t == person)
                for s, t, f in ev.forwarded
            )
            return PhaseView(
                phase, done, f"forward {phase.file} to {person or 'the helper'}", person=person
            )
        state = states[phase.role.key]
        items: list[tuple[str, Purpose]] = []
        for leg in phase.legs:
            owner = leg.owner_fixed
            if owner is None and leg.owner_role is not None:
                s = states.get(leg.owner_role)
                owner = s.person if s is not None and s.bound else None
            if owner is None:  # whose item is not known until someone lends one
                owner = self._used_owner(ev, leg)
            if owner is not None:
                items.append((f"{leg.item_type}:{owner}", leg.purpose))
        done = len(items) == len(phase.legs) and all(used_after(ev, i, p, after) for i, p in items)
        person = state.person if state.bound else None
        place = self.roles.meeting_place(phase.role, person, ltm) if person else None
        what = ", ".join(purpose_text(self.office, p, i) for i, p in items) or role_text(
            phase.role, self.office
        )
        who = (
            person_name(self.office, person)
            if person
            else f"whoever can {role_text(phase.role, self.office)}"
        )
        return PhaseView(
            phase,
            done,
            f"hand-over with {who}: {what}",
            person=person,
            place=place,
            items=items,
            pending=[(i, p) for i, p in items if not used_after(ev, i, p, after)],
        )

    @staticmethod
    def _used_owner(ev: Evidence, leg: Leg) -> str | None:
        for code in ev.codes:
            if code.used and code.item.split(":", 1)[0] == leg.item_type:
                return code.item.split(":", 1)[1]
        return None

    def _why(self, state: RoleState) -> str:
        role = state.role
        what = role_text(role, self.office)
        if not state.excluded and state.group is None:
            return f"nobody I know of can {what}"
        if role.kind == "receive" and list(state.excluded) == [role.requester]:
            return "you did not come to the robot to collect it"
        parts = [f"{self.office.person(p).name} {why}" for p, why in state.excluded.items()]
        if state.group is not None:
            parts.append(f"nobody in the {self.office.group(state.group).name} group could help")
        return f"no one could {what}: " + ", ".join(parts)

    # -- the Plan of the trace -----------------------------------------------------------
    def plan_model(self, agenda: Agenda, notes: str = "") -> Plan:
        subgoals: list[SubGoal] = []
        for n, view in enumerate(agenda.tasks):
            for p in view.phases:
                subgoals.append(SubGoal(description=f"task {n + 1}: {p.description}", done=p.done))
        subgoals.append(SubGoal(description="tell the requester the outcome", done=False))
        goal = "; ".join(describe(t.compiled.task, self.office) for t in agenda.tasks)
        return Plan(
            goal=goal or "understand the request", subgoals=subgoals[:30], notes=notes[:2000]
        )


def used_after(ev: Evidence, item: str, purpose: str, after: dict[str, int]) -> bool:
    """Whether a code for ``purpose`` on ``item`` was used, after the code that brought the
    item to the requester in an earlier task (``after``: its index among the codes)."""
    start = after.get(item, -1)
    return any(
        c.used and c.item == item and c.purpose == purpose
        for k, c in enumerate(ev.codes)
        if k > start
    )


def _first_used(ev: Evidence, item: str, purpose: str, person: str, start: int) -> int | None:
    """The index of the first code for ``purpose`` on ``item`` that ``person`` used after the
    code at ``start`` (the hand-over that finished an earlier task on the item)."""
    return next(
        (
            k
            for k, c in enumerate(ev.codes)
            if k > start
            and c.used
            and c.item == item
            and c.purpose == purpose
            and c.person == person
        ),
        None,
    )


def _moved(view: TaskView) -> bool:
    """Whether a hand-over of the task has happened (a code of it was used)."""
    return any(p.done and isinstance(p.phase, Handover) for p in view.phases)


def _uses(phase: Phase, key: str) -> bool:
    if isinstance(phase, Handover):
        return phase.role.key == key or any(leg.owner_role == key for leg in phase.legs)
    if isinstance(phase, Forward):
        return phase.target_role.key == key
    return False


def _role_key(phase: Phase) -> str | None:
    if isinstance(phase, Confirm | Handover):
        return phase.role.key
    return phase.target_role.key


def role_text(role: Role, office: Office) -> str:
    """What the role's person is asked to do, in words: "lend a stapler"."""
    thing = item_type_name(office, role.item_type) if role.item_type else "it"
    if thing == "it":
        a_one = thing
    else:  # "an umbrella", "some glue", "a pair of scissors"
        a_one = a_thing(thing, mass=office.item_type(role.item_type or "").mass)
    the = thing if thing == "it" else f"the {thing}"
    shape = kind_shape(role.kind)
    if shape is not None and shape != "make":  # the office's own name for its operation
        op = role.operation or next((o.id for o in office.with_shape(shape)), None)
        if op is None:
            return f"{role.kind} {the}"
        # "patch the inner tube" of "patch a tube", "print a banner from the file"
        operation = office.operation(op)
        return f"{operation_verb(operation.name, product_words(operation))} {the}"
    return wording("role_wording").get(role.kind, "help").format(a=a_one, the=the)


def describe(task: Task, office: Office, you: str | None = None) -> str:
    """A short English description of a task, for plans and summaries (``you``: the person
    spoken to, named "you")."""

    def name(person: str | None) -> str:
        if person is not None and person == you:
            return "you"
        return person_name(office, person) if person else "anyone"

    def owner_s(person: str | None) -> str:
        if person is not None and person == you:
            return "your"
        if person is not None and not office.is_person(person):
            return "the"  # owned by nobody (a facility's supply)
        return f"{name(person)}'s"

    item = office.item_type(task.item).name if task.item else "item"
    if task.owner is not None and task.item and office.is_supply(f"{task.item}:{task.owner}"):
        whose = item_phrase(office, f"{task.item}:{task.owner}")  # owned by nobody
    else:
        stuff = bool(task.item) and office.item_type(task.item or "").mass
        whose = f"{name(task.owner)}'s {item}" if task.owner else a_thing(item, mass=stuff)
    whose = f"your {item}" if task.owner is not None and task.owner == you else whose
    to = name(task.recipient)
    op = operation_of(office, task)
    # the office's word ("scan"), without an object of its own ("patch" of "patch a tube")
    operation = office.operation(op) if op else None
    verb = operation_verb(operation.name, product_words(operation)) if operation else task.kind
    spec = task_kinds.kind(task.kind)
    template = spec.todo
    if op is not None and office.operation(op).sends_out and task.destination and spec.todo_sent:
        template = spec.todo_sent  # sent outside: where to, not for whom
    return template.format(
        dest=task.destination,
        verb=verb,
        whose=whose,
        owner_s=owner_s(task.owner),
        file=file_noun(office),
        to=to,
        by=name(task.actor),
        item=item,
    )


def _with_role(compiled: CompiledTask, old: Role, new: Role) -> CompiledTask:
    """``compiled`` with role ``old`` replaced by ``new`` in its roles and phases."""

    def swap(role: Role) -> Role:
        return new if role == old else role

    def phase(p: Phase) -> Phase:
        if isinstance(p, Confirm):
            return Confirm(swap(p.role))
        if isinstance(p, Forward):
            return Forward(p.source, swap(p.target_role), p.file)
        return Handover(swap(p.role), p.legs)

    return CompiledTask(
        compiled.task, [swap(r) for r in compiled.roles], [phase(p) for p in compiled.phases]
    )
