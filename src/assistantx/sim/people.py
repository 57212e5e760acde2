"""Rule-based simulated people (DESIGN §4), deterministic.

An available person answers a question about an item truthfully, agrees to a request they can
do, sends their file when asked for it, and does a locker hand-over when the robot is at their
place, they hold a QR code for it, and they were told what to do. An unavailable person never
answers and never hands anything over. In a group chat, the available members who can help
answer; the others stay silent.
"""

from __future__ import annotations

from dataclasses import dataclass

from assistantx.sim.understanding import (
    REQUEST_OPERATION,
    is_question,
    mentioned_item_types,
    mentioned_requests,
)
from assistantx.sim.world import LOCKER, World
from assistantx.wording import item_phrase


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
    if request == "sign":
        return True
    if request == "seal":
        return world.owns(person, "seal")
    if request == "send_file":
        return world.owns(person, "file")
    operation = REQUEST_OPERATION.get(request)
    return operation is not None and world.can_operate(person, operation)


def direct_reply(world: World, person: str, text: str) -> Reply | None:
    """What ``person`` answers to a direct message (None: no answer)."""
    if not world.available(person):
        return None
    types = [t for t in mentioned_item_types(world.office, text) if t != "file"]
    requests = mentioned_requests(text)
    wants_file = "file" in mentioned_item_types(world.office, text) and "send_file" in requests
    if wants_file:
        return Reply(person, "Sure, here is my file.", (f"file:{person}",))
    service = [r for r in requests if r not in ("send_file",)]
    if service:
        request = service[0]
        if can_do(world, person, request):
            return Reply(person, f"Yes, I can do that ({request}). I'll be at the robot's locker.")
        return Reply(person, f"Sorry, I can't help with that ({request}).")
    belongings = [t for t in types if world.office.item_type(t).kind == "belonging"]
    if belongings:
        t = belongings[0]
        if world.owns(person, t):
            return Reply(person, f"Yes, I have a {_item_name(world, t)}. Happy to lend it.")
        return Reply(person, f"No, I don't have a {_item_name(world, t)}.")
    if is_question(text):
        return Reply(person, "Yes, I'm here. What do you need?")
    return Reply(person, "OK, thanks!") if "robot" in text.lower() else None


def group_replies(world: World, members: list[str], text: str) -> list[Reply]:
    """Answers in a group chat: only available members who can help speak up."""
    types = [
        t
        for t in mentioned_item_types(world.office, text)
        if world.office.item_type(t).kind == "belonging"
    ]
    requests = [r for r in mentioned_requests(text) if r != "send_file"]
    replies: list[Reply] = []
    for person in members:
        if not world.available(person):
            continue
        if requests and can_do(world, person, requests[0]):
            replies.append(Reply(person, f"I can help with that ({requests[0]})."))
        elif not requests and types and world.owns(person, types[0]):
            replies.append(
                Reply(person, f"I have a {_item_name(world, types[0])}, you can borrow it.")
            )
    return replies


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
            return None  # e.g. a lunch kept in the fridge they sit next to
        return f"I don't have {thing}."
    if purpose == "collect":
        return None if where == LOCKER else missing
    if purpose in ("sign", "seal", "copy", "heat"):
        if where != LOCKER:
            return missing
        if purpose == "seal" and not world.owns(person, "seal"):
            return "I don't have the seal."
        if purpose in ("copy", "heat") and not world.can_operate(person, purpose):
            return f"I can't {purpose} things here."
        return None
    if purpose == "produce":
        operation = {
            "coffee": "coffee",
            "water": "water",
            "snack": "vend",
            "printout": "print",
            "copy": "copy",
        }.get(item_type)
        if operation is None or not world.can_operate(person, operation):
            return f"I can't make {_item_name(world, item_type)} here."
        facility = next(f for f in world.office.facilities if operation in f.operations)
        if place != facility.location:
            return f"The robot is not at the {facility.name}."
        if item_type == "printout":
            owner = item.split(":", 1)[1]
            if (person, f"file:{owner}") not in world.received:
                what = _thing(world, f"file:{owner}", person)
                return f"I haven't received the file to print ({what})."
        if item_type == "copy":
            owner = item.split(":", 1)[1]
            if world.holder.get(f"document:{owner}") != LOCKER:
                what = _thing(world, f"document:{owner}", person)
                return f"The document to copy ({what}) is not in the locker."
        return None
    return f"I don't know how to {purpose}."


def perform_handover(world: World, time: float, person: str, purpose: str, item: str) -> None:
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
        world.produce(time, f"copy:{item.split(':', 1)[1]}", by=person)
    elif purpose == "heat":
        world.heated.add(item)
        world.note(time, "heated", item=item, by=person)
    elif purpose == "produce":
        item_type, _, owner = item.partition(":")
        if item_type == "printout":
            world.printed.add(f"file:{owner}")
        if item_type == "copy":
            world.copied.add(f"document:{owner}")
        world.produce(time, item, by=person)
