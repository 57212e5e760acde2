"""From a base instruction's spec to what a task needs: goal milestones, roles and visits.

A *role* is a person the task needs and whose availability is unknown until asked: a named
person (Zhang, who must sign) or anyone able among candidates (an owner of a stapler, a guard
of the printer). A *visit* is one stop of the robot: drive to a place, hand out QR codes to one
person, wait there for the hand-over. A plan is the roles to resolve, the cyber actions that
need no visit (forwarding a file), the visits, and the final deliveries, in that order.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Literal

from assistantx.core import task_kinds
from assistantx.core.goals import Milestone
from assistantx.core.office import Office, Operation
from assistantx.core.task_spec import BaseInstruction, Part, made_kind, part_operation
from assistantx.core.wording import file_noun, product_words, verb_it, with_object
from assistantx.memory.graph import LongTermMemory

RoleKind = Literal["named", "owner", "guard"]


@dataclass(frozen=True)
class Role:
    """A person slot; ``key`` identifies it so that parts needing the same person share it."""

    key: str
    kind: RoleKind
    question: str  # what the assistant asks a candidate
    group_question: str | None = None  # what it asks a group when every candidate is away
    person: str | None = None  # named roles
    item_type: str | None = None  # owner roles
    facility: str | None = None  # guard roles
    wants_file: bool = False  # the answer carries the person's file
    # the person's own item leaves them: a helper found in a group chat is then asked in
    # their own chat, where the consent guard (runtime/consent.py) looks for the yes
    own_item_leaves: bool = False


@dataclass(frozen=True)
class Code:
    role: str  # role key, or "@requester"
    item: str  # item id; "{role}" is replaced by the role's person when resolved
    purpose: str
    operation: str | None = None  # the office operation of a work step (scan, not copy)
    destination: str | None = None  # where a send-out operation sends the item
    send_to: str | None = None  # whom a made file (a PDF) goes to by message, if not its owner


@dataclass(frozen=True)
class Visit:
    """Drive to ``place`` (a role's person, the requester or a facility id), hand out codes."""

    place: str
    person: str  # role key or "@requester"
    codes: tuple[Code, ...]


@dataclass(frozen=True)
class Forward:
    source: str  # role key or "@requester"
    target: str  # role key, person id or "@requester"
    # the file item sent ("audio:ines"), where the work takes one of the office's several
    # kinds of file; None: the source's own file (``Office.file_of``)
    file: str | None = None


@dataclass
class TaskPlan:
    roles: list[Role] = field(default_factory=list)
    forwards: list[Forward] = field(default_factory=list)
    visits: list[Visit] = field(default_factory=list)
    deliveries: list[tuple[str, Code]] = field(default_factory=list)  # recipient → collect code
    goal: list[Milestone] = field(default_factory=list)
    must_be_available: set[str] = field(default_factory=set)  # told without being asked
    # what to do instead when a role of this plan finds nobody: the same instruction with
    # nobody's kept item (the keeper is away), borrowing a colleague's at hand instead
    fallback: TaskPlan | None = None
    uses_kept: bool = False  # an item nobody named comes from where it is kept

    def role(self, key: str) -> Role:
        return next(r for r in self.roles if r.key == key)

    def add_role(self, role: Role) -> None:
        """Add ``role``; a person already in the plan for another part (the one who receives
        the requester's item and lends their own in return) is asked both things at once, so
        the lend question, where their yes is given, is never dropped."""
        for n, known in enumerate(self.roles):
            if known.key != role.key:
                continue
            if role.question not in known.question:
                self.roles[n] = replace(
                    known,
                    question=f"{known.question} {role.question}",
                    wants_file=known.wants_file or role.wants_file,
                    own_item_leaves=known.own_item_leaves or role.own_item_leaves,
                )
            return
        self.roles.append(role)

    def add_goal(self, milestone: Milestone) -> None:
        if milestone not in self.goal:
            self.goal.append(milestone)


REQUESTER = "@requester"


def facility_for(office: Office, operation: str) -> str:
    return next(f.id for f in office.facilities if operation in f.operations)


def candidates(role: Role, ltm: LongTermMemory, requester: str) -> list[str]:
    """Who memory says could fill the role (unordered; the policy orders them)."""
    if role.kind == "named":
        assert role.person is not None
        return [role.person]
    if role.kind == "owner":
        assert role.item_type is not None
        found = [p for p in ltm.owners(role.item_type) if _at_hand(role, p, ltm.office)]
    else:
        assert role.facility is not None
        found = ltm.guards(role.facility)
    return [p for p in found if p != requester]


def able(role: Role, office: Office, person: str) -> bool:
    """Whether ``person`` could fill the role in truth (used to find group helpers)."""
    if role.kind == "named":
        return person == role.person
    if role.kind == "owner":
        owns = any(o.type == role.item_type for o in office.person(person).owns)
        return owns and _at_hand(role, person, office)
    return person in office.facility(role.facility or "").guards


def _at_hand(role: Role, person: str, office: Office) -> bool:
    """Whether an owner has their item at hand: one kept in a cupboard is the keeper's to
    hand out (it is fetched through the keeper, never from the owner's desk)."""
    if role.item_type is None or not office.is_person(person):
        return True
    try:
        return office.keeper(person, role.item_type) is None
    except KeyError:
        return True


def build_plan(base: BaseInstruction, office: Office, *, kept: bool = True) -> TaskPlan:
    """``kept``: an item nobody named comes from where one is kept (a cupboard); the plan's
    ``fallback`` is the same instruction borrowing a colleague's instead."""
    plan = TaskPlan()
    a = base.requester
    who = office.person(a).name
    for part in base.parts:
        _add_part(plan, part, a, who, office, use_kept=kept)
    plan.add_goal({"informed": a})
    if plan.uses_kept:
        other = build_plan(base, office, kept=False)
        owners = [r for r in other.roles if r.kind == "owner"]
        if all(any(able(r, office, p.id) for p in office.people if p.id != a) for r in owners):
            plan.fallback = other  # someone has one at hand to lend
    return plan


def _named(person: str, question: str, *, wants_file: bool = False) -> Role:
    return Role(
        key=f"person:{person}",
        kind="named",
        question=question,
        person=person,
        wants_file=wants_file,
    )


def _recipient(plan: TaskPlan, part: Part, who: str) -> str:
    """Who a made thing (a printout, a copy, a tea) is brought to: the part's ``to``, asked to
    be at their desk, else the requester."""
    if part.to is None:
        return REQUESTER
    target = _named(
        part.to, f"Could you be at your desk? The robot brings you something from {who}."
    )
    plan.add_role(target)
    return target.key


def _machine_guard(office: Office, part: Part, who: str) -> tuple[Operation, Role]:
    """The operation a print or copy part runs, and the role of the guard asked to run it on
    ``who``'s item at its machine."""
    op = part_operation(office, part)
    place_name = office.facility(facility_for(office, op.id)).name
    thing = office.item_type(op.input or "").name
    whose_thing = f"{who}'s {thing}"
    role = _guard(
        office,
        op.id,
        f"Could you {with_object(op.name, whose_thing, made=product_words(op))} at the "
        f"{place_name}?",
        f"Could anyone {with_object(op.name, whose_thing, made=product_words(op))} at the "
        f"{place_name}?",
    )
    return op, role


def _guard(office: Office, operation: str, question: str, group_question: str | None) -> Role:
    return _guard_of(facility_for(office, operation), question, group_question)


def _guard_of(facility: str, question: str, group_question: str | None) -> Role:
    """Whoever guards ``facility``, asked ``question`` (``group_question`` in a group)."""
    return Role(
        key=f"guard:{facility}",
        kind="guard",
        question=question,
        group_question=group_question,
        facility=facility,
    )


def _put_in(plan: TaskPlan, item: str, a: str, who: str, office: Office) -> None:
    """The hand-over that puts the requester's own ``item`` into the locker for a part that
    works on it (a copy, a signature, a heat).

    Parts run in order, as the embedded planner runs a request's tasks: when an earlier part
    hands the item back to the requester ("get my drawings signed, then courier them"), that
    hand-back happens here, before this part, at the same stop where the requester puts it in
    again (with whatever else the earlier parts bring them), and the earlier part's "the
    requester holds it" is no longer the end of the task: this part says where it ends. Else
    an item kept at a facility (a film in the picture archive, a lunch in the fridge) is taken
    out by the facility's keeper, who is asked; the requester's request is the owner's yes.
    """
    earlier = [(to, c) for to, c in plan.deliveries if to == REQUESTER]
    if any(c.item == item for _, c in earlier):
        plan.deliveries = [(to, c) for to, c in plan.deliveries if to != REQUESTER]
        plan.visits.append(Visit(REQUESTER, REQUESTER, tuple(c for _, c in earlier)))
        plan.goal = [m for m in plan.goal if m != {"holds": [a, item]}]
        plan.visits.append(Visit(REQUESTER, REQUESTER, (Code(REQUESTER, item, "deposit"),)))
        return
    type_id = item.partition(":")[0]
    keeper = office.keeper(a, type_id)
    if keeper is None:  # the requester has it
        plan.visits.append(Visit(REQUESTER, REQUESTER, (Code(REQUESTER, item, "deposit"),)))
        return
    thing = office.item_type(type_id).name
    role = _guard_of(
        keeper.id,
        f"Could you take {who}'s {thing} out of the {keeper.name} for the robot?",
        f"Could anyone take {who}'s {thing} out of the {keeper.name}?",
    )
    plan.add_role(role)
    plan.visits.append(Visit(keeper.id, role.key, (Code(role.key, item, "deposit"),)))


def _add_part(
    plan: TaskPlan, part: Part, a: str, who: str, office: Office, *, use_kept: bool = True
) -> None:
    kind = "make" if made_kind(office, part.kind) else part.kind  # "coffee": make a coffee
    match kind:
        case "fetch":
            item_type = part.item or ""
            name = office.item_type(item_type).name
            # no owner named: the one kept at a facility (the cupboard's label maker) first
            owner = part.owner or (office.kept_owner(item_type, besides=a) if use_kept else None)
            keeper = office.keeper(owner, item_type) if owner else None
            plan.uses_kept |= keeper is not None and part.owner is None
            if keeper is not None:  # kept in a cupboard: its guard takes it out
                item = f"{item_type}:{owner}"
                supply = office.is_supply(item)  # owned by nobody: no one's yes to ask
                if owner != a and not supply:  # the owner's own yes: a keeper can't give it
                    plan.add_role(
                        _named(
                            owner or "",
                            f"Could you let {who} have your {name} from the {keeper.name}?",
                        )
                    )
                whose = "the" if supply else f"{owner}'s"
                role = _guard_of(
                    keeper.id,
                    f"Could you take {whose} {name} out of the {keeper.name}?",
                    f"Could anyone take the {name} out of the {keeper.name}?",
                )
                plan.add_goal({"holds": [a, item]})
                plan.add_role(role)
                plan.visits.append(Visit(keeper.id, role.key, (Code(role.key, item, "deposit"),)))
                plan.deliveries.append((REQUESTER, Code(REQUESTER, item, "collect")))
                return
            if part.owner is not None:
                role = _named(part.owner, f"Could you lend {who} your {name}?")
                item = f"{item_type}:{part.owner}"
                plan.add_goal({"holds": [a, item]})
            else:
                role = Role(
                    key=f"owner:{item_type}",
                    kind="owner",
                    question=f"Could you lend {who} your {name}?",
                    group_question=f"Does anyone have a {name} {who} could borrow?",
                    item_type=item_type,
                    own_item_leaves=True,
                )
                item = f"{item_type}:{{{role.key}}}"
                plan.add_goal({"holds": [a, f"{item_type}:*"]})
            plan.add_role(role)
            plan.visits.append(Visit(role.key, role.key, (Code(role.key, item, "deposit"),)))
            plan.deliveries.append((REQUESTER, Code(REQUESTER, item, "collect")))
        case "deliver":
            to = part.to or ""
            item = f"{part.item}:{a}"
            role = _named(
                to, f"Could you be at your desk? The robot brings you something from {who}."
            )
            plan.add_role(role)
            back = [(t, c) for t, c in plan.deliveries if t == REQUESTER and c.item == item]
            if back:
                # an earlier part's work leaves it in the locker ("get Amara to sign my
                # drawings and then take them to Luc"): it goes on from there, not back first
                plan.deliveries = [d for d in plan.deliveries if d not in back]
                plan.goal = [m for m in plan.goal if m != {"holds": [a, item]}]
            else:
                # from where it is: the requester's desk, or the cupboard its keeper opens (a
                # torque wrench kept in the parts store)
                _put_in(plan, item, a, who, office)
            plan.deliveries.append((role.key, Code(role.key, item, "collect")))
            plan.add_goal({"holds": [to, item]})
        case "print":
            op, role = _machine_guard(office, part, who)
            source, made = op.input or "", op.product or ""
            plan.add_role(role)
            product = f"{made}:{a}"
            plan.forwards.append(Forward(REQUESTER, role.key, office.file_of(a, source)))
            place = role.facility or ""
            plan.visits.append(Visit(place, role.key, (Code(role.key, product, "produce"),)))
            recipient = _recipient(plan, part, who)
            plan.deliveries.append((recipient, Code(recipient, product, "collect")))
            plan.add_goal({"printed": f"{source}:{a}"})
            plan.add_goal({"holds": [part.to or a, product]})
        case "copy":
            op, role = _machine_guard(office, part, who)
            source, made = op.input or "", op.product or ""
            plan.add_role(role)
            doc = f"{source}:{a}"
            _put_in(plan, doc, a, who, office)
            by_message = office.item_type(made).electronic
            # scanned to PDF for someone else: the operator is told whom to send it to
            send_to = part.to if by_message and part.to not in (None, a) else None
            plan.visits.append(
                Visit(
                    role.facility or "",
                    role.key,
                    (Code(role.key, doc, "copy", op.id, send_to=send_to),),
                )
            )
            plan.deliveries.append((REQUESTER, Code(REQUESTER, doc, "collect")))
            plan.add_goal({"copied": doc})
            if by_message:  # scanned to PDF: the file is sent by message, to whom it is for
                plan.add_goal({"received": [send_to or a, f"{made}:{a}"]})
                plan.add_goal({"holds": [a, doc]})
                return
            # the copy goes to the named recipient; the original comes back to its owner
            recipient = _recipient(plan, part, who)
            plan.deliveries.append((recipient, Code(recipient, f"{made}:{a}", "collect")))
            plan.add_goal({"holds": [part.to or a, f"{made}:{a}"]})
            plan.add_goal({"holds": [a, doc]})
        case _ if task_kinds.kind(part.task_kind()).by_person:
            # a person's work on the requester's paper (sign, seal ...), from the table: a
            # named doer, or whoever owns the kind's tool (the seal)
            spec = task_kinds.kind(part.task_kind())
            paper = task_kinds.item_type_of(spec.id, office) or ""
            doc = f"{paper}:{a}"
            whose = f"{who}'s {office.item_type(paper).name}"
            ask = spec.ask or spec.id + " {whose}"
            tool = task_kinds.tool_type(spec.id, office)
            if spec.tool is None:
                doer = part.signer or ""
                role = _named(doer, f"Could you {ask.format(whose=whose, your='your')}?")
                plan.add_goal({spec.milestone: [doc, doer]})
            else:
                role = Role(
                    key=f"owner:{tool}",
                    kind="owner",
                    question=f"Could you {ask.format(whose=whose, your='your')}?",
                    group_question=f"Could anyone {ask.format(whose=whose, your='the')}?",
                    item_type=tool,
                )
                plan.add_goal({spec.milestone: doc})
            plan.add_role(role)
            _put_in(plan, doc, a, who, office)
            plan.visits.append(
                Visit(role.key, role.key, (Code(role.key, doc, spec.purpose or ""),))
            )
            plan.deliveries.append((REQUESTER, Code(REQUESTER, doc, "collect")))
            plan.add_goal({"holds": [a, doc]})
        case "make":
            op = part_operation(office, part)
            made = op.product or ""
            place_name = office.facility(facility_for(office, op.id)).name
            thing = office.item_type(made).name
            role = _guard(
                office,
                op.id,
                f"Could you get {thing} for {who} from the {place_name}?",
                f"Could anyone get {thing} for {who} from the {place_name}?",
            )
            plan.add_role(role)
            # made for whoever it is for (Mark's tea), as the embedded planner names it
            product = f"{made}:{part.to or a}"
            plan.visits.append(
                Visit(role.facility or "", role.key, (Code(role.key, product, "produce"),))
            )
            recipient = _recipient(plan, part, who)
            plan.deliveries.append((recipient, Code(recipient, product, "collect")))
            plan.add_goal({"holds": [part.to or a, product]})
        case "heat":
            op = part_operation(office, part)
            source = op.input or ""
            kept = f"{source}:{a}"
            thing = office.item_type(source).name
            place_name = office.facility(facility_for(office, op.id)).name
            # who sends it outside is told where to, as the embedded planner tells them
            to = f" to {part.destination}" if op.sends_out and part.destination else ""
            said = with_object(op.name, f"{who}'s {thing}", bare=bool(to), made=product_words(op))
            asked = (f"{said} at the {place_name}{to}?", "")
            if to:
                # by the service's own verb, the place outside last ("courier Ana's proof to
                # the print works at Felling"): no word of the place is read as the work
                sent = verb_it(op, part.destination, obj=f"{who}'s {thing}")
                asked = (f"{sent}?", f" The robot will bring it to you at the {place_name}.")
            op_role = _guard(
                office,
                op.id,
                f"Could you {asked[0]}{asked[1]}",
                f"Could anyone {asked[0]}{asked[1]}",
            )
            _put_in(plan, kept, a, who, office)
            plan.add_role(op_role)
            plan.visits.append(
                Visit(
                    op_role.facility or "",
                    op_role.key,
                    (
                        Code(
                            op_role.key,
                            kept,
                            "heat",
                            op.id,
                            part.destination if op.sends_out else None,
                        ),
                    ),
                )
            )
            plan.add_goal({"heated": kept})
            if op.returns_item:  # a shredded or faxed-out document does not come back
                # to whom the part says ("laminate my poster and take it over to Drew"), as
                # the task it reads as (``Part.task``: recipient ``to``) and the embedded
                # planner hand it; else back to the requester
                recipient = _recipient(plan, part, who)
                plan.deliveries.append((recipient, Code(recipient, kept, "collect")))
                plan.add_goal({"holds": [part.to or a, kept]})
        case "forward_file":
            to = part.to or ""
            plan.forwards.append(Forward(REQUESTER, to))
            plan.must_be_available.add(to)
            plan.add_goal({"received": [to, office.file_of(a)]})
        case "get_file":
            owner = part.owner or ""
            # named as this office names its files (a "script", a "drawing"): asked for by
            # that name, the owner knows which file is meant
            thing = file_noun(office)
            role = _named(owner, f"Could you send me your {thing} for {who}?", wants_file=True)
            plan.add_role(role)
            plan.forwards.append(Forward(role.key, REQUESTER))
            plan.add_goal({"received": [a, office.file_of(owner)]})
