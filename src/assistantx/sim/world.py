"""The simulated office's truth: where everyone and everything is, who is available, what has
been printed, signed, sealed, copied, heated, made, received, and who was told what.

The world only changes through its methods, each of which logs what happened, so tests and the
evaluator can see every hand-over (and catch one to the wrong person).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

from assistantx.core import task_kinds
from assistantx.core.errors import ActionError
from assistantx.core.goals import parse_milestone
from assistantx.core.office import Office

LOCKER = "locker"


# World events kept (an evaluation episode logs a few dozen; a service about one per
# instruction): at 5,000 a service's log grew for its first 11,000 instructions.
LOG_KEEP = 256


@dataclass
class WorldEvent:
    time: float
    kind: str
    detail: dict[str, Any]


@dataclass
class World:
    office: Office
    unavailable: set[str] = field(default_factory=set)
    holder: dict[str, str] = field(default_factory=dict)  # item id → person / locker / location
    signed: set[tuple[str, str]] = field(default_factory=set)  # (document, signer)
    sealed: set[tuple[str, str]] = field(default_factory=set)  # (document, sealer)
    printed: set[str] = field(default_factory=set)  # file ids
    copied: set[str] = field(default_factory=set)  # document ids
    heated: set[str] = field(default_factory=set)
    # the work of a person-to-person kind added to the table of kinds: (milestone, item, doer)
    worked: set[tuple[str, str, str]] = field(default_factory=set)
    made: set[str] = field(default_factory=set)  # product item ids
    received: set[tuple[str, str]] = field(default_factory=set)  # (person, file)
    messages_to: dict[str, int] = field(default_factory=dict)  # person → messages received
    # supplies owned by nobody with a count (item id → how many are left); a supply without
    # a count is never used up
    stock: dict[str, int] = field(default_factory=dict)
    log: list[WorldEvent] = field(default_factory=list)

    @classmethod
    def from_office(cls, office: Office, unavailable: Iterable[str] = ()) -> World:
        world = cls(office=office, unavailable=set(unavailable))
        for person_id in world.unavailable:
            office.person(person_id)  # unknown ids fail here, not mid-run
        for p in office.people:
            for o in p.owns:
                if office.item_type(o.type).physical:
                    world.holder[p.item_id(o.type)] = o.at or p.id
        for f in office.facilities:
            for supply in f.supplies:
                world.holder[f.item_id(supply.type)] = f.location
                if supply.count is not None:
                    world.stock[f.item_id(supply.type)] = supply.count
        return world

    def _supply_place(self, item_id: str) -> str | None:
        if not self.office.is_supply(item_id):
            return None
        return self.office.facility(item_id.partition(":")[2]).location

    def in_stock(self, item_id: str) -> bool:
        """Whether a supply owned by nobody still has one at its place to take out (one
        taken from a supply without a count leaves the place as full as before)."""
        if not self.office.is_supply(item_id):
            return False
        return self.stock.get(item_id, 1) > 0

    # -- facts ---------------------------------------------------------------------------
    def available(self, person_id: str) -> bool:
        return person_id not in self.unavailable

    def owns(self, person_id: str, item_type: str) -> bool:
        return any(o.type == item_type for o in self.office.person(person_id).owns)

    def owners(self, item_type: str) -> list[str]:
        return self.office.owners_of(item_type)

    def locker_contents(self) -> list[str]:
        return sorted(i for i, h in self.holder.items() if h == LOCKER)

    def can_operate(self, person_id: str, operation: str) -> bool:
        return any(
            operation in f.operations and person_id in f.guards for f in self.office.facilities
        )

    def places_of(self, person_id: str) -> set[str]:
        """Where a person can meet the robot: their desk and the facilities they guard."""
        places = {self.office.person(person_id).location}
        places.update(f.location for f in self.office.facilities if person_id in f.guards)
        return places

    # -- changes -------------------------------------------------------------------------
    def note(self, time: float, kind: str, **detail: Any) -> None:
        self.log.append(WorldEvent(time, kind, detail))
        if len(self.log) > 2 * LOG_KEEP:  # a service's world runs for months: keep the recent
            del self.log[:-LOG_KEEP]

    def record_message(self, time: float, person_id: str) -> None:
        self.messages_to[person_id] = self.messages_to.get(person_id, 0) + 1

    def move_item(self, time: float, item_id: str, to: str, by: str) -> None:
        frm = self.holder.get(item_id)
        if item_id in self.stock and frm != to and frm == self._supply_place(item_id):
            self.stock[item_id] = max(0, self.stock[item_id] - 1)  # one fewer on the shelf
        self.holder[item_id] = to
        self.note(time, "item_moved", item=item_id, frm=frm, to=to, by=by)

    def produce(self, time: float, item_id: str, by: str) -> None:
        self.made.add(item_id)
        self.holder[item_id] = LOCKER
        self.note(time, "produced", item=item_id, by=by)

    def receive_file(self, time: float, person_id: str, file_id: str) -> None:
        self.received.add((person_id, file_id))
        self.note(time, "file_received", person=person_id, file=file_id)

    def set_available(self, person_id: str, available: bool) -> None:
        self.office.person(person_id)
        if available:
            self.unavailable.discard(person_id)
        else:
            self.unavailable.add(person_id)

    # -- milestones ----------------------------------------------------------------------
    def check(self, milestone: dict[str, Any]) -> bool:
        name, args = parse_milestone(milestone)
        match name:
            case "holds":  # ``type:*``: any item of the type but the holder's own
                person, wanted = args
                return any(
                    self.holder.get(i) == person
                    for i in self.matching(wanted)
                    if not (wanted.endswith(":*") and i.partition(":")[2] == person)
                )
            case "signed":
                return (args[0], args[1]) in self.signed
            case "sealed":
                return any(doc == args[0] for doc, _ in self.sealed)
            case "printed":
                return args[0] in self.printed
            case "copied":
                return args[0] in self.copied
            case "heated":
                return args[0] in self.heated
            case "received":
                return (args[0], args[1]) in self.received
            case "made":
                return args[0] in self.made
            case "informed":
                return self.messages_to.get(args[0], 0) > 0
            case _ if task_kinds.milestone_arity(name) is not None:  # an added kind's work
                doc, *doer = args  # the item, and its named doer when the kind names one
                return any(
                    (m, d) == (name, doc) and (not doer or by == doer[0])
                    for m, d, by in self.worked
                )
        raise ActionError(f"unknown milestone {milestone!r}")  # pragma: no cover

    def matching(self, item: str) -> list[str]:
        """``type:owner`` as is; ``type:*`` = every item of that type the world knows."""
        item_type, _, owner = item.partition(":")
        if owner != "*":
            return [item]
        return sorted(i for i in self.holder if i.partition(":")[0] == item_type)

    def handovers(self) -> list[WorldEvent]:
        return [e for e in self.log if e.kind == "item_moved"]

    def sent_out(self) -> list[WorldEvent]:
        """Items a colleague sent outside the office (faxed, couriered), each with the
        words of the code that asked them to: where it went is what those words said."""
        return [e for e in self.log if e.kind == "sent_out"]
