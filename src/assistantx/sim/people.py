"""Rule-based simulated people (DESIGN §4), deterministic.

An available person answers a question about an item truthfully, agrees to a request they can
do, sends their file when asked for it, and does a locker hand-over when the robot is at their
place, they hold a QR code for it, and they were told what to do. An unavailable person never
answers and never hands anything over. In a group chat, the available members who can help
answer; the others stay silent.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from assistantx.core import task_kinds
from assistantx.core.office import Facility, Operation, OperationShape, Ownership
from assistantx.core.task_schema import FILE_KIND, kind_shape
from assistantx.core.wording import a_thing, item_phrase
from assistantx.sim.file_recipient import file_recipient
from assistantx.sim.understanding import (
    asks_to_do,
    asks_to_receive,
    facility_requests,
    is_question,
    mentioned_item_types,
    mentioned_requests,
    possessor,
)
from assistantx.sim.world import LOCKER, World


@dataclass(frozen=True)
class Reply:
    person: str
    text: str
    files: tuple[str, ...] = ()


def _item_name(world: World, type_id: str) -> str:
    return world.office.item_type(type_id).name


def _thing(world: World, item: str, speaker: str) -> str:
    """An item as ``speaker`` names it: "my stapler", "Lee Ming's document"."""
    if item.partition(":")[2] == speaker:
        return f"my {_item_name(world, item.partition(':')[0])}"
    return item_phrase(world.office, item)


def can_do(world: World, person: str, request: str) -> bool:
    if world.can_operate(person, request):
        return True  # an office's own operation, also one named like a kind ("seal" a bag)
    if request in task_kinds.person_kinds():  # by hand: with its tool, if it needs one (seal)
        tool = task_kinds.tool_type(request, world.office)
        # a tool the office keeps in a safe or cupboard is not at hand to work with, by the
        # oracle's rule (``oracle.plan.able``): the dataset generator's dry run and a group
        # chat's volunteers must agree on who can do the work
        return not task_kinds.needs_tool(request) or (
            tool is not None and world.owns(person, tool) and kept_at(world, person, tool) is None
        )
    if request == FILE_KIND:
        return any(
            world.office.item_type(o.type).kind == "electronic" for o in _owns(world, person)
        )
    return world.can_operate(person, request)


def _owns(world: World, person: str) -> list[Ownership]:
    return list(world.office.person(person).owns)


def _operation_here(
    world: World, person: str, place: str, shapes: tuple[OperationShape, ...], told: str = ""
) -> Operation | None:
    """The operation of one of ``shapes`` that ``person`` runs at a facility at ``place``; of
    several (copy and scan at one machine), the one the code's message asks for ("scan it")."""
    office = world.office
    found: list[Operation] = []
    for f in office.facilities:
        if f.location != place or person not in f.guards:
            continue
        for op_id in f.operations:
            op = office.operation(op_id)
            if op.shape(office) in shapes:
                found.append(op)
    # the name split as the message is ("date-stamp" is the words date and stamp in both)
    words = set(re.findall(r"[a-z]+", told.lower()))
    asked = [op for op in found if set(re.findall(r"[a-z]+", op.name.lower())) <= words]
    # else by the operation's own verb ("scan it" asks for "scan to PDF", whose whole name the
    # code's message need not say): without it, the machine's first service ran instead
    verbed = [op for op in found if words & {v.lower() for v in op.verbs if " " not in v}]
    return next(iter(asked or verbed or found), None)


def direct_reply(world: World, person: str, text: str) -> Reply | None:
    """What ``person`` answers to a direct message (None: no answer)."""
    if not world.available(person):
        return None
    if asks_to_receive(text):  # "could you be at your desk to receive a delivery from Lee?"
        return Reply(person, "Yes, I'm here. I'll be at my desk.")
    electronic = {t.id for t in world.office.item_types if t.kind == "electronic"}
    named = mentioned_item_types(world.office, text)
    types = [t for t in named if t not in electronic]
    requests = mentioned_requests(world.office, text)
    wants_file = bool(electronic & set(named)) and FILE_KIND in requests
    if wants_file:
        # the file of the type asked for ("your slides" where slides are a type of their own)
        kinds = [t for t in named if t in electronic]
        asked = kinds[0] if len(kinds) == 1 else None
        return Reply(person, "Sure, here is my file.", (world.office.file_of(person, asked),))
    service = [r for r in requests if r != FILE_KIND]
    if not service and not types and asks_to_do(text):
        service = facility_requests(world.office, text)  # "... through the 3D printer?"
    if service:
        request = service[0]
        if can_do(world, person, request):
            return Reply(person, f"Yes, I can do that ({request}). I'll be at the robot's locker.")
        return Reply(person, f"Sorry, I can't help with that ({request}).")
    if types:
        return Reply(person, _about_item(world, person, types[0], text))
    if is_question(text):
        return Reply(person, "Yes, I'm here. What do you need?")
    return Reply(person, "OK, thanks!") if "robot" in text.lower() else None


def _about_item(world: World, person: str, type_id: str, text: str) -> str:
    """The answer to a question about an item: someone else's item they keep (a lunch in the
    fridge they look after), their own, or one they keep for the office."""
    name = _item_name(world, type_id)
    whose = possessor(world.office, text, reader=person)
    if whose is not None:  # "take Zhang's lunch out of the fridge": a keeper's job
        where = world.holder.get(f"{type_id}:{whose}")
        if where is not None and where != whose and where in world.places_of(person):
            return (
                f"Yes, I can take {_thing(world, f'{type_id}:{whose}', person)} out for the robot."
            )
        if not world.owns(person, type_id):
            return f"Sorry, I don't have {_thing(world, f'{type_id}:{whose}', person)}."
    if world.owns(person, type_id):
        keeper = kept_at(world, person, type_id)
        if keeper is not None:  # kept in a cupboard: their yes, and who takes it out
            return _kept_answer(world, person, name, keeper)
        if world.office.item_type(type_id).kind == "belonging":
            return f"Yes, I have {a_thing(name)}. Happy to lend it."
        return f"Yes, you can have my {name}."
    kept = [
        i
        for i, where in world.holder.items()
        if i.startswith(f"{type_id}:")
        and where in world.places_of(person)
        and where != person
        and (not world.office.is_supply(i) or world.in_stock(i))  # none left: they say so
    ]
    if kept:  # kept in a cupboard they run
        return f"Yes, I can take the {name} out for the robot."
    return f"No, I don't have {a_thing(name)}."


def group_replies(world: World, members: list[str], text: str) -> list[Reply]:
    """Answers in a group chat: only available members who can help speak up."""
    types = [
        t
        for t in mentioned_item_types(world.office, text)
        if world.office.item_type(t).kind == "belonging"
    ]
    requests = [r for r in mentioned_requests(world.office, text) if r != FILE_KIND]
    if not requests and not types and asks_to_do(text):
        requests = facility_requests(world.office, text)  # "... through the 3D printer?"
    replies: list[Reply] = []
    for person in members:
        if not world.available(person):
            continue
        if requests and can_do(world, person, requests[0]):
            replies.append(Reply(person, f"I can help with that ({requests[0]})."))
        elif not requests and types and _can_bring(world, person, types[0]):
            replies.append(
                Reply(person, f"I have {a_thing(_item_name(world, types[0]))}, you can borrow it.")
            )
    return replies


def kept_at(world: World, person: str, type_id: str) -> Facility | None:
    """The facility the office declares keeps ``person``'s item of this type (a cupboard, a
    fridge), or None when it is with them."""
    try:
        return world.office.keeper(person, type_id)
    except KeyError:
        return None


def _kept_answer(world: World, person: str, name: str, keeper: Facility) -> str:
    """An owner asked for an item the office keeps for them: yes (the owner's own consent),
    and where it really is, so nobody expects them to bring it from their desk."""
    if person in keeper.guards:
        return f"Yes, you can have my {name}. I'll take it out of the {keeper.name} for the robot."
    others = [world.office.person(g).name for g in keeper.guards if g != person]
    who = " or ".join(others) if others else "whoever looks after it"
    return (
        f"Yes, you can have my {name}. It is kept in the {keeper.name}, not with me: "
        f"{who} can take it out for the robot."
    )


def _can_bring(world: World, person: str, type_id: str) -> bool:
    """Whether ``person`` has their item of this type at hand to lend from their desk (on
    them, or where they can get at it). An item the office declares kept at a facility is
    never at hand, even when its owner runs that facility or sits by it: it is fetched from
    there through the keeper, by the same rule as the oracle's (``oracle.plan.able``), so a
    group chat's volunteers are the ones the oracle and the dataset generator expect."""
    if not world.owns(person, type_id) or kept_at(world, person, type_id) is not None:
        return False
    where = world.holder.get(f"{type_id}:{person}", person)
    return where == person or where in world.places_of(person)


def handover_problem(world: World, person: str, purpose: str, item: str, place: str) -> str | None:
    """Why ``person`` cannot do ``purpose`` with ``item`` at the locker now (None: they can)."""
    where = world.holder.get(item)
    item_type = item.split(":", 1)[0]
    thing = _thing(world, item, person)
    missing = f"{thing[0].upper()}{thing[1:]} is not in the locker."
    if purpose == "deposit":
        if where == person:
            return None
        if where is not None and where == place and place in world.places_of(person):
            if world.office.is_supply(item) and not world.in_stock(item):
                return f"There is no {_item_name(world, item_type)} left here."
            return None  # e.g. a lunch kept in the fridge they sit next to
        return f"I don't have {thing}."
    if purpose == "collect":
        return None if where == LOCKER else missing
    if purpose in task_kinds.work_purposes():
        if where != LOCKER:
            return missing
        tool = task_kinds.tool_type(purpose, world.office)
        if task_kinds.needs_tool(purpose) and (tool is None or not world.owns(person, tool)):
            return f"I don't have the {_item_name(world, tool) if tool else purpose}."
        shape = kind_shape(purpose)
        if shape is not None and _operation_here(world, person, place, (shape,)) is None:
            ops = world.office.with_shape(shape)  # the office's word: "scan", not "copy"
            return f"I can't {ops[0].name if ops else purpose} things here."
        return None
    if purpose == "produce":
        op = world.office.making(item_type)
        if op is None or not world.can_operate(person, op.id):
            return f"I can't make {_item_name(world, item_type)} here."
        if not any(f.location == place for f in world.office.offering(op.id)):
            return f"The robot is not at a place that offers {op.name}."
        owner = item.split(":", 1)[1]
        if op.input is not None and op.shape(world.office) == "render":
            # their own file they have; anyone else's must have been sent to them
            if person != owner and (person, f"{op.input}:{owner}") not in world.received:
                what = _thing(world, f"{op.input}:{owner}", person)
                return f"I haven't received the file to {op.name} ({what})."
        if op.input is not None and op.shape(world.office) == "transform":
            if world.holder.get(f"{op.input}:{owner}") != LOCKER:
                what = _thing(world, f"{op.input}:{owner}", person)
                return f"The item to {op.name} ({what}) is not in the locker."
        return None
    return f"I don't know how to {purpose}."


def perform_handover(
    world: World, time: float, person: str, purpose: str, item: str, place: str, told: str = ""
) -> None:
    """Do the physical act once the door is open (the caller checked handover_problem)."""
    if purpose == "deposit":
        world.move_item(time, item, LOCKER, by=person)
    elif purpose == "collect":
        world.move_item(time, item, person, by=person)
    elif purpose == "sign":
        world.signed.add((item, person))
        world.note(time, "signed", item=item, by=person)
    elif purpose == "seal":
        world.sealed.add((item, person))
        world.note(time, "sealed", item=item, by=person)
    elif purpose == "copy":
        world.copied.add(item)
        op = _operation_here(world, person, place, ("transform",), told)
        product = (op.product if op is not None else None) or item.split(":", 1)[0]
        owner = item.split(":", 1)[1]
        if world.office.item_type(product).electronic:  # a PDF: sent by message, to whom
            # the code's message says (its owner unless it names another)
            to = file_recipient(world.office, told, owner, person)
            world.receive_file(time, to, f"{product}:{owner}")
        else:
            world.produce(time, f"{product}:{owner}", by=person)
    elif purpose == "heat":
        world.heated.add(item)
        world.note(time, "heated", item=item, by=person)
        op = _operation_here(world, person, place, ("treat",), told)
        if op is not None and not op.returns_item:  # shredded, faxed out: it stays there
            world.move_item(time, item, place, by=person)
        if op is not None and op.sends_out:  # sent where their code's message said
            world.note(time, "sent_out", item=item, by=person, told=told)
    elif (spec := task_kinds.of_purpose(purpose)) is not None and spec.by_person:
        world.worked.add((spec.milestone, item, person))  # an added kind's work by hand
        world.note(time, spec.milestone, item=item, by=person)
    elif purpose == "produce":
        item_type, _, owner = item.partition(":")
        op = world.office.making(item_type)
        if op is not None and op.input is not None:
            if op.shape(world.office) == "render":
                world.printed.add(f"{op.input}:{owner}")
            else:
                world.copied.add(f"{op.input}:{owner}")
        world.produce(time, item, by=person)
