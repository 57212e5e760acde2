"""Roles in a task (who lends, who prints, who signs, who receives) and who fills them.

A role has candidates from memory (known owners, the guards of a facility, or one named
person), ordered by availability and then travel distance from the robot. Who fills it is
read from the evidence: the first candidate who said yes, skipping anyone who said no, stayed
silent past a wait, is known to be away, or failed to come to the robot. When every known
candidate is out, the role is put to a group chat the requester belongs to; when that finds
nobody either, the role is exhausted and the task cannot be done.

The question texts are deterministic, so the evidence finds which role a question was for by
its text, and they name the item or the request so a colleague understands them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Literal

from assistantx.agents.symbolic.answers import stance
from assistantx.agents.symbolic.evidence import Evidence, Question
from assistantx.core import language, task_kinds
from assistantx.core.name_parts import greeting_name
from assistantx.core.office import Office, Operation
from assistantx.core.task_schema import TaskKind, kind_shape
from assistantx.core.wording import a_thing, product_words, with_object
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.names import normalize

DistanceFn = Callable[[str, str], float]
# A role is one of the person-to-person parts of a transfer, or the task kind it fills.
# ``allow``: the owner's own yes for their item that a keeper hands over (no hand-over of theirs).
RoleKind = Literal["lend", "give", "keep", "allow", "receive"] | TaskKind
RoleStatus = Literal["bound", "ask", "waiting", "group", "group_waiting", "exhausted"]

# How long an availability observation stays true (s): people come and go.
AVAILABILITY_TTL_S = 1800.0


@dataclass(frozen=True)
class Role:
    key: str  # unique in the frame, e.g. "0.source"
    kind: RoleKind
    requester: str
    fixed: str | None = None  # the one person who can do it
    item_type: str | None = None
    item_owner: str | None = None  # whose item the request is about (for the wording)
    facility: str | None = None  # where a guard meets the robot
    beneficiary: str | None = None  # for whom
    operation: str | None = None  # the office operation a facility role runs
    destination: str | None = None  # where a send-out operation sends it (requester's words)
    send_to: str | None = None  # whom a file the work makes (a PDF) goes to, if not its owner

    @property
    def confirm(self) -> bool:
        """Whether the person must be asked first (the requester needs no asking)."""
        return self.fixed != self.requester

    @property
    def asks_ownership(self) -> bool:
        return self.kind == "lend"

    @property
    def own_item_leaves(self) -> bool:
        """Whether the person's own item leaves them: their yes must be in their own chat
        (runtime/consent.py), so a yes in a group chat is followed by a direct question."""
        return self.kind in ("lend", "give")


@dataclass
class RoleState:
    role: Role
    status: RoleStatus
    person: str | None = None  # bound, to ask, or awaited
    group: str | None = None
    asked: list[str] = field(default_factory=list)
    excluded: dict[str, str] = field(default_factory=dict)  # person → why

    @property
    def bound(self) -> bool:
        return self.status == "bound"


class Roles:
    """Questions, candidates and resolution over one office and its memory."""

    def __init__(self, office: Office, distance: DistanceFn) -> None:
        self.office = office
        self.distance = distance

    # -- wording -------------------------------------------------------------------------
    def _name(self, person: str) -> str:
        return self.office.person(person).name

    def _whose(self, role: Role) -> str:
        owner = role.item_owner or role.requester
        if not self.office.is_person(owner):
            return "the"  # a supply owned by nobody: "take the pen out of the cupboard"
        return f"{self._name(owner)}'s"

    def _thing(self, role: Role) -> str:
        return self.office.item_type(role.item_type).name if role.item_type else "item"

    def _operation(self, role: Role) -> Operation | None:
        """The operation the role runs at its facility."""
        shape = kind_shape(role.kind)
        if role.facility is not None:
            for op_id in self.office.facility(role.facility).operations:
                op = self.office.operation(op_id)
                if op.shape(self.office) == shape and (
                    role.operation is None or op.id == role.operation
                ):
                    return op
        return None

    def _operation_name(self, role: Role) -> str:
        """How the office names the operation the role runs at its facility ("print")."""
        op = self._operation(role)
        return _as_verb(op) if op is not None else role.kind

    def _done_to(self, role: Role, obj: str) -> str:
        """The operation said with its object ("print Ana's file", "patch Ana's inner tube",
        "print a banner from Ana's file" where the banner is what it makes)."""
        op = self._operation(role)
        made = product_words(op) if op is not None else frozenset()
        return with_object(self._operation_name(role), obj, made=made)

    def _making_named(self, role: Role) -> str | None:
        """The name of the operation that makes the role's product from nothing, where that
        name says the product ("make up a sample board", "make coffee"): how its keeper is
        asked to make one. None where the name does not say it ("frank" for a stamped
        envelope): the product is named instead."""
        if role.item_type is None:
            return None
        op = self.office.making(role.item_type)
        if op is None or op.input is not None:
            return None
        product = self.office.item_type(role.item_type)
        name = f" {normalize(op.name)} "
        if any(f" {normalize(n)} " in name for n in (product.name, *product.synonyms) if n):
            return op.name
        return None

    def _used_up(self, role: Role) -> bool:
        return role.item_type is not None and self.office.item_type(role.item_type).consumable

    def _request(self, role: Role, *, anyone: bool) -> str:
        """The request, for one person ('your') or for a group ('a')."""
        thing = self._thing(role)
        beneficiary = self._name(role.beneficiary or role.requester)
        place = self.office.facility(role.facility).name if role.facility else ""
        match role.kind:
            case "lend" if self._used_up(role):  # paper is given, not lent
                return f"spare {beneficiary} some {'' if anyone else 'of your '}{thing}"
            case "lend":
                return f"lend {beneficiary} {a_thing(thing) if anyone else f'your {thing}'}"
            case "give":
                return f"hand over your {thing} for {beneficiary}"
            case "keep":
                return f"take {self._whose(role)} {thing} out of the {place} for the robot"
            case "allow":
                return f"let {beneficiary} have your {thing} from the {place}"
            case "receive" if role.item_type and role.item_owner == role.fixed:
                return (  # given back to its owner: named, so the yes is the owner's own
                    f"be at your desk soon to receive your {thing} back from "
                    f"{self._name(role.requester)}"
                )
            case "receive":
                return (
                    f"be at your desk soon to receive a delivery from {self._name(role.requester)}"
                )
            case "print" | "copy":
                said = self._done_to(role, f"{self._whose(role)} {thing}")
                if role.send_to is not None and (made := self._made_file(role)) is not None:
                    # the file goes by message: whom to, so a yes agrees to sending it there
                    return (
                        f"{said} at the {place} and send the {made} to {self._name(role.send_to)}"
                    )
                return f"{said} at the {place}"
            case kind if task_kinds.kind_of(kind) and task_kinds.kind(kind).ask:
                # a person's work from the table ("sign X's document", "stamp ... with a seal")
                ask = task_kinds.kind(kind).ask or ""
                whose = f"{self._whose(role)} {thing}"
                return ask.format(whose=whose, your="a" if anyone else "your")
            case "produce" if (making := self._making_named(role)) is not None:
                # "make up a sample board": the keeper is asked to make it, not to find one
                return f"{making} for {beneficiary} at the {place}"
            case "produce":
                return f"get {thing} for {beneficiary} from the {place}"
            case "heat" if role.destination:  # the one who faxes it must know where to
                # by the service's own verb ("courier X's document to Y"), the place outside
                # last; the facility where the robot brings it is said after the question
                obj = f"{self._whose(role)} {thing}"
                return with_object(self._send_verb(role), obj, role.destination)
            case "heat":
                said = self._done_to(role, f"{self._whose(role)} {thing}")
                return f"{said} in the {place}"
            case "send_file":
                return f"send me your {thing} for {beneficiary}"
        raise ValueError(role.kind)  # pragma: no cover

    def _made_file(self, role: Role) -> str | None:
        """The name of the electronic file the role's operation makes ("PDF"), if it does."""
        if role.operation is None:
            return None
        product = self.office.operation(role.operation).product
        if product is None or not self.office.item_type(product).electronic:
            return None
        return self.office.item_type(product).name

    def _send_verb(self, role: Role) -> str:
        """The verb a send-out service is asked for by: its first declared verb ("courier"
        of "send by courier"), else its name as a verb ("fax")."""
        op_id = role.operation
        if op_id is None and role.facility is not None:
            shape = kind_shape(role.kind)
            ops = self.office.facility(role.facility).operations
            op_id = next(
                (o for o in ops if self.office.operation(o).shape(self.office) == shape), None
            )
        if op_id is None:
            return self._operation_name(role)
        op = self.office.operation(op_id)
        return op.verbs[0] if op.verbs else _as_verb(op)

    def question(self, role: Role, person: str) -> str:
        first = greeting_name(self.office.person(person))
        comes = role.kind not in ("send_file", "allow")
        tail = " The robot will come to you for the hand-over." if comes else ""
        if role.kind == "heat" and role.destination and role.facility is not None:
            place = self.office.facility(role.facility).name
            tail = f" The robot will bring it to you at the {place}."
        return f"Hi {first}, could you {self._request(role, anyone=False)}?{tail}"

    def group_question(self, role: Role) -> str:
        tail = " Please reply here if you can; the robot will come to you."
        return f"Hi all, could anyone {self._request(role, anyone=True)}?{tail}"

    def inform(self, role: Role, person: str) -> str:
        first = greeting_name(self.office.person(person))
        return (
            f"Hi {first}, the robot is on its way to you: could you "
            f"{self._request(role, anyone=False)}? I'll send you a locker code."
        )

    # -- candidates ----------------------------------------------------------------------
    def meeting_place(self, role: Role, person: str, ltm: LongTermMemory) -> str:
        """Where the robot meets ``person`` for this role: a facility, else their desk."""
        if role.facility is not None and person in ltm.guards(role.facility):
            return ltm.facility_location(role.facility)
        return ltm.location_of(person)

    def candidates(self, role: Role, ltm: LongTermMemory) -> list[str]:
        if role.fixed is not None:
            return [role.fixed]
        if role.kind == "lend" and role.item_type is not None:
            # an owner whose one is kept at a facility (in a cupboard) does not have it at hand
            found = [
                p
                for p in ltm.owners(role.item_type)
                if p != role.beneficiary and self.office.keeper(p, role.item_type) is None
            ]
        elif task_kinds.needs_tool(role.kind):  # whoever owns the tool (the seal)
            tool = task_kinds.tool_type(role.kind, self.office)
            found = ltm.owners(tool) if tool else []
        elif role.facility is not None:
            found = ltm.guards(role.facility)
        else:
            found = []
        return [p for p in found if p != role.requester]

    def order(
        self,
        role: Role,
        people: list[str],
        ltm: LongTermMemory,
        robot_place: str | None,
        now: float,
    ) -> list[str]:
        here = robot_place or self.office.robot.home

        def key(person: str) -> tuple[int, float, str]:
            known = _fresh_availability(ltm, person, now)
            rank = 0 if known == "available" else 1
            return rank, self.distance(here, self.meeting_place(role, person, ltm)), person

        return sorted(people, key=key)

    # -- resolution ----------------------------------------------------------------------
    def resolve(self, role: Role, ltm: LongTermMemory, ev: Evidence, now: float) -> RoleState:
        if not role.confirm:
            failed = ev.failed_handover(role.requester)
            if failed is not None:
                return RoleState(role, "exhausted", excluded={role.requester: "did not come"})
            return RoleState(role, "bound", person=role.requester)
        state = RoleState(role, "exhausted")
        people = [
            p
            for p in self.candidates(role, ltm)
            if not self._lent_out(role, p, ltm) or ev.asked(p, self.question(role, p))
        ]
        group_q = self._group_asked(role, ev)
        helpers: list[str] = []
        if group_q is not None:
            helpers = [
                t.person
                for t in ev.answers(group_q)
                if ev.stance_of(group_q, t.person) == "yes"
                and t.person not in helpers
                and t.person != role.requester  # never the helper of their own request
                # a facility's job is done by its guards: "I have one, you can borrow it" to
                # "could anyone take it out of the cupboard?" is no yes, nor the plotter's
                # keeper's yes to "could anyone 3D print it at the 3D printer?" (the
                # oracle's rule; the consent guard sends work codes only to the guards)
                and (role.facility is None or t.person in ltm.guards(role.facility))
            ]
        for person in [*people, *helpers]:
            why = self._exclusion(role, person, ltm, ev, now)
            if why is not None:
                state.excluded[person] = why
        # who said yes, in the order they said it
        for person in self._yes_in_order(role, [*people, *helpers], ev):
            if person not in state.excluded:
                state.status, state.person = "bound", person
                return state
        for person in people:
            q = ev.asked(person, self.question(role, person))
            if q is not None:
                state.asked.append(person)
                if ev.pending(q) and person not in state.excluded:
                    state.status, state.person = "waiting", person
                    return state
        remaining = [p for p in people if p not in state.excluded and p not in state.asked]
        if remaining:
            state.status = "ask"
            state.person = self.order(role, remaining, ltm, ev.robot_place, now)[0]
            return state
        if role.fixed is not None:
            return state
        for person in helpers if role.own_item_leaves else []:
            # said yes in the group: now asked in their own chat, where consent is given
            if person in state.excluded:
                continue
            q = ev.asked(person, self.question(role, person))
            if q is None:
                state.status, state.person = "ask", person
                return state
            state.asked.append(person)
            if ev.pending(q):
                state.status, state.person = "waiting", person
                return state
        if group_q is not None:
            state.group = group_q.contact
            if ev.pending(group_q):
                state.status = "group_waiting"
            return state
        group = self.group_for(role.requester)
        if group is not None:
            state.status, state.group = "group", group
        return state

    @staticmethod
    def _lent_out(role: Role, person: str, ltm: LongTermMemory) -> bool:
        """Memory knows (from a hand-over) that someone else holds ``person``'s item: they
        still own it, but cannot lend it now, so they are not asked (unless this very
        instruction asked them: then it is this hand-over that moved it)."""
        return (
            role.kind == "lend"
            and role.item_type is not None
            and ltm.lent_out(person, role.item_type) is not None
        )

    def _taken_since_yes(
        self, role: Role, person: str, ltm: LongTermMemory, ev: Evidence
    ) -> str | None:
        """Why ``person`` cannot lend now although they may have said yes: another
        instruction's hand-over took their item after their answer (two instructions asked
        them at nearly the same time and both heard yes; the first took it). Without this,
        the second sent them a code for an item they no longer had. A yes given after that
        hand-over is theirs to give (the item came back)."""
        if role.kind != "lend" or role.item_type is None:
            return None
        item = f"{role.item_type}:{person}"
        taken = ltm.taken_by_another(item, ev.instruction_id)
        if taken is None:
            return None
        q = ev.asked(person, self.question(role, person))
        yes = [
            t.time
            for t in (ev.answers(q) if q is not None else [])
            if t.person == person and stance(t.text) == "yes"
        ]
        if yes and max(yes) > taken.time:
            return None
        return f"their {role.item_type} was taken for another errand"

    def group_for(self, requester: str) -> str | None:
        """The largest group chat the requester belongs to."""
        mine = [g for g in self.office.groups if requester in g.members]
        if not mine:
            return None
        return max(mine, key=lambda g: (len(g.members), g.id)).id

    def _group_asked(self, role: Role, ev: Evidence) -> Question | None:
        text = self.group_question(role)
        found = [q for q in ev.questions if q.group and q.text == text]
        return found[-1] if found else None

    def _yes_in_order(self, role: Role, people: list[str], ev: Evidence) -> list[str]:
        said: list[tuple[float, str]] = []
        group_q = self._group_asked(role, ev)
        for person in dict.fromkeys(people):
            q = ev.asked(person, self.question(role, person))
            # a yes in the group binds only where nothing of the person's own leaves them
            for question in (q,) if role.own_item_leaves else (q, group_q):
                if question is None:
                    continue
                turns = [t for t in ev.answers(question) if t.person == person]
                if turns and ev.stance_of(question, person) == "yes":
                    said.append((turns[-1].time, person))
        if role.kind == "send_file":  # the file itself is the yes
            said += [
                (0.0, p)
                for p in people
                if self.office.file_of(p, role.item_type) in ev.files_received.get(p, [])
            ]
        return [p for _, p in sorted(said)]

    def _yes_in_group_since(self, role: Role, person: str, q: Question, ev: Evidence) -> bool:
        """Whether ``person``, who answered ``q`` in their own chat, said yes in the group
        after it: the newer answer wins. Not where their own item leaves them (that yes is
        given in their own chat, runtime/consent.py)."""
        group_q = self._group_asked(role, ev)
        if role.own_item_leaves or group_q is None:
            return False
        mine = [t.time for t in ev.answers(q) if t.person == person]
        since = max(mine) if mine else q.time
        later = [t for t in ev.answers(group_q) if t.person == person and t.time > since]
        return bool(later) and stance(later[-1].text) == "yes"

    def _exclusion(
        self, role: Role, person: str, ltm: LongTermMemory, ev: Evidence, now: float
    ) -> str | None:
        failed = ev.failed_handover(person)
        if failed is not None:
            return (
                f"could not hand over: {failed.complaint}"
                if failed.complaint
                else ("did not come to the robot")
            )
        taken = self._taken_since_yes(role, person, ltm, ev)
        if taken is not None:
            return taken
        q = ev.asked(person, self.question(role, person))
        if q is not None:
            said = ev.stance_of(q, person)
            if said == "no":
                # "sorry, I can't" in private, then "I can help" in the group: the newer wins
                return None if self._yes_in_group_since(role, person, q, ev) else "said no"
            if said is None and ev.expired(q):
                return "did not answer"
            if (
                role.kind == "send_file"
                and said == "yes"
                and ev.expired(q)
                and (
                    self.office.file_of(person, role.item_type)
                    not in ev.files_received.get(person, [])
                )
            ):
                return "did not send the file"
            return None
        if _fresh_availability(ltm, person, now) == "unavailable":
            return "known to be away"
        if person in ev.said_away and role.fixed is None:  # a named person is still asked
            return f"the requester said {ev.said_away[person]!r}"
        if role.item_type and (person, role.item_type) in ev.said_unusable:
            return f"their {role.item_type} is {ev.said_unusable[(person, role.item_type)]}"
        if (
            role.asks_ownership
            and role.item_type
            and ltm.ownership(person, role.item_type) is False
        ):
            return f"has no {role.item_type}"
        return None


def _fresh_availability(ltm: LongTermMemory, person: str, now: float) -> str:
    value = ltm.availability(person)
    seen = ltm.availability_observed_at(person)
    if value != "unknown" and seen is not None and now - seen > AVAILABILITY_TTL_S:
        return "unknown"
    return value


def _as_verb(op: Operation) -> str:
    """The operation as the verb of "could you ...": its name where the name opens with a
    verb ("print", "make coffee"), else its first declared verb ("vet" for a "legal read":
    "could you legal read ..." is no English a colleague reads as asked, and the verb is the
    word the office says the work is asked for by)."""
    first = op.name.split()[0].lower() if op.name.split() else ""
    if op.verbs and not language.verb_lemmas(first):
        return op.verbs[0]
    return op.name
