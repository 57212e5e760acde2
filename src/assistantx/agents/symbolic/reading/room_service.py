"""The requester's own thing taken to a room whose machines work on it: "can you take my wheel
down to wrapping", where the wrapping room has a wax bath and a vacuum packer that both work on
cheeses. The robot hands things to people, never to rooms, and nobody is said to get it: the
thing goes to the room for what the room does to it, and comes back to the requester. Read as
it stood, the request was a transfer of the requester's own thing to the requester (nothing
done), or who in the room should get it was asked.

The services are the operations that the room's facilities run (a room named, or a facility
that runs nothing, named for its room) whose input is the thing's type, that the office can
run and that send nothing out of the office. One: that service is asked ("... to wax it"),
read as any service on the thing. Several: which is asked ("What should I do with your cheese
in the Wrapping room: wax it, or vacuum pack it?"), and the answer's verb chooses. None: as
before (who there gets it is asked).

Only where the request is one transfer of the requester's own thing to the requester, with no
source: a colleague said to get it ("Zhang needs it"), or the thing brought from somewhere, is
read as before; so is a facility named with its own work ("to the microwave"), which the
frames read as that work already.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.machine_choice import Choice, with_service
from assistantx.agents.symbolic.reading.room_receiver import rooms_taken_to
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language
from assistantx.core.office import Office, Operation
from assistantx.core.task_schema import TaskFrame


def own_thing_to_room(frame: TaskFrame, requester: str) -> str | None:
    """The item type of the frame's one task, where it is a transfer of the requester's own
    thing to the requester from nowhere said; None otherwise."""
    if len(frame.tasks) != 1:
        return None
    t = frame.tasks[0]
    if t.kind != "transfer" or t.item is None or t.source is not None:
        return None
    if t.owner != requester or t.recipient not in (requester, None):
        return None
    return t.item


def room_services(
    office: Office, tokens: Sequence[Token], mentions: Sequence[Mention], item: str
) -> tuple[str, list[Operation]] | None:
    """The one room the words take a thing to, and the services of its facilities that work
    on ``item`` (see the module); None where no one room, or a facility with work of its own,
    is named after "to"."""
    rooms: set[str] = set()
    for place in rooms_taken_to(tokens, mentions):
        if any(loc.id == place for loc in office.locations):
            rooms.add(place)
            continue
        facility = office.facility(place)
        if facility.operations:
            return None  # "to the microwave": its work, read by the frames
        rooms.add(facility.location)
    if len(rooms) != 1:
        return None
    (room,) = rooms
    services: list[Operation] = []
    for f in office.facilities:
        if f.location != room:
            continue
        for op_id in f.operations:
            op = office.operation(op_id)
            if op.input != item or op.sends_out or not op.verbs or not office.runnable(op_id):
                continue
            if op not in services:
                services.append(op)
    name = next(loc.name for loc in office.locations if loc.id == room)
    return name, services


def room_service_question(office: Office, item: str, room: str, ops: Sequence[Operation]) -> str:
    """ "What should I do with your cheese in the Wrapping room: wax it, or vacuum pack it?" """
    said = [f"{op.verbs[0]} it" for op in ops]
    which = f"{', '.join(said[:-1])}, or {said[-1]}"
    return f"What should I do with your {office.item_type(item).name} in the {room}: {which}?"


def room_service_answered(ops: Sequence[Operation], answer: str) -> Operation | None:
    """The one service the answer names by a word of one of its verbs (any form) that no
    other service's verbs have ("wax", "vacuum pack it", "the vacuum packer")."""
    words = set(language.words(language.fold(answer)))

    def forms(op: Operation) -> set[str]:
        return {f for v in op.verbs for w in v.split() for f in language.verb_forms(w)}

    found = [
        op
        for op in ops
        if words & (forms(op) - {f for other in ops if other is not op for f in forms(other)})
    ]
    return found[0] if len(found) == 1 else None


def with_room_service(office: Office, text: str, op: Operation) -> str:
    """The request with the service said as its purpose ("take my wheel down to wrapping" →
    "take my wheel down to wrapping to wax it"), which the reader reads as that service."""
    item = op.input or ""
    name = office.item_type(item).name
    return with_service(text, Choice(op.verbs[0], tuple(op.verbs), item, name))
