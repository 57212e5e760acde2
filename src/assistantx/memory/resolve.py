"""Grounding: resolve the names in actions to ids of the office, or fail with a message.

Names are matched tolerantly (case, spacing, titles, possessives; small typos only when one
candidate is close). Ambiguity is an error listing the candidates, never a guess. The error
texts are written to be fed back to a language model as they are.

Actions (:meth:`Resolver.ground`) and memory updates (:meth:`Resolver.ground_update`) are
grounded here and only here: the loop and every reasoner share one rule for what a name means.
"""

from __future__ import annotations

import difflib
import re

from assistantx.core.actions import (
    Action,
    ForwardFile,
    Inform,
    Inquire,
    Move,
    SendQR,
    Stop,
    Wait,
    WaitInPlace,
)
from assistantx.core.errors import AmbiguousNameError, GroundingError, UnknownNameError
from assistantx.core.goals import Milestone, parse_milestone
from assistantx.core.office import FILE_WORD, Office, PersonId
from assistantx.memory.graph import LOCKER
from assistantx.memory.names import NameIndex, normalize
from assistantx.memory.updates import (
    AvailabilityUpdate,
    ItemLocationUpdate,
    MemoryUpdate,
    OwnershipUpdate,
)

# What people and models call the robot's own locker, an item holder that is in no office file.
LOCKER_NAMES = ("the locker", "robot locker", "the robot's locker", "the robot locker")

ContactKind = str  # "person" | "group"


class Resolver:
    """Name → id lookups over one office."""

    def __init__(self, office: Office) -> None:
        self.office = office
        self._hints: list[str | None] = [None, None]
        self.people = NameIndex()
        for p in office.people:
            self.people.add(p.id, [p.name, *p.aliases], words=p.name.split())
        self.groups = NameIndex()
        for g in office.groups:
            self.groups.add(g.id, [g.name, f"{g.name} group", f"{g.name} chat"], g.name.split())
        self.facilities = NameIndex()
        for f in office.facilities:
            self.facilities.add(f.id, [f.name, *f.synonyms])
        self.locations = NameIndex()
        for loc in office.locations:
            self.locations.add(loc.id, [loc.name])
        self.item_types = NameIndex()
        file_type = office.file_type()
        for t in office.item_types:
            plural = [f"{n}s" for n in (t.name, *t.synonyms) if not n.endswith("s")]
            # "file" (the messenger's neutral name, ports.messenger.persons_file, and the
            # plain word) is also the office's electronic type, whatever its id ("script"),
            # below any type the office itself names so
            generic = [FILE_WORD, f"{FILE_WORD}s"] if t.id == file_type else []
            self.item_types.add(t.id, [t.name, *t.synonyms, *plural], words=generic)
        self.lockers = NameIndex()
        self.lockers.add(LOCKER, LOCKER_NAMES)
        # How each contact is written in the office file, only case and spacing folded: the
        # tie-break when a tolerant match finds a person and a group (see ``contact``).
        self._written: dict[str, dict[str, set[str]]] = {"person": {}, "group": {}}
        for p in office.people:
            for spelling in (p.id, p.id.replace("_", " "), p.name, *p.aliases):
                self._written["person"].setdefault(_as_written(spelling), set()).add(p.id)
        for g in office.groups:
            for spelling in (g.id, g.id.replace("_", " "), g.name):
                self._written["group"].setdefault(_as_written(spelling), set()).add(g.id)

    # -- single lookups ------------------------------------------------------------------
    def person(self, name: str) -> PersonId:
        return PersonId(
            self._one(
                "person", name, self.people.lookup(name), self._people_hint(), self.people.keys()
            )
        )

    def people_list(self, names: str) -> tuple[PersonId, ...]:
        """Comma-separated names ("Zhang, Mr Wang") → person ids, each matched like one name."""
        return tuple(dict.fromkeys(self.person(n) for n in names.split(",") if n.strip()))

    def group(self, name: str) -> str:
        return self._one(
            "group chat", name, self.groups.lookup(name), self._groups_hint(), self.groups.keys()
        )

    def contact(self, name: str) -> tuple[ContactKind, str]:
        """A person or a group chat. A name that matches both is ambiguous."""
        people = self.people.lookup(name)
        groups = self.groups.lookup(name)
        if people and groups:
            people, groups = self._as_declared(name, people, groups)
        if people and groups:
            raise AmbiguousNameError(
                "contact",
                name,
                f"Contact {name!r} matches both people {people} and group chats {groups}; "
                "use an id.",
                [*people, *groups],
            )
        if groups:
            return "group", self._one("group chat", name, groups, self._groups_hint())
        return "person", self._one(
            "contact",
            name,
            people,
            self._people_hint() + " " + self._groups_hint(),
            self.people.keys() + self.groups.keys(),
        )

    def _as_declared(
        self, name: str, people: list[str], groups: list[str]
    ) -> tuple[list[str], list[str]]:
        """A name the tolerant match finds as a person and as a group: an id, then a
        spelling the office declares, written as it is (case and spacing aside), decides.
        Group ``station`` and the alias "the station manager" both normalize to "station"
        (titles and articles are dropped), yet "station" is the group and "the station
        manager" the person; a name written like both stays ambiguous."""
        raw = name.strip()
        if raw in groups and raw not in people:
            return [], [raw]
        if raw in people and raw not in groups:
            return [raw], []
        key = _as_written(name)
        as_person = sorted(self._written["person"].get(key, set()) & set(people))
        as_group = sorted(self._written["group"].get(key, set()) & set(groups))
        if as_person and not as_group:
            return as_person, []
        if as_group and not as_person:
            return [], as_group
        return people, groups

    def place(self, name: str) -> str:
        """A location id from a location, a facility or a person's name (their desk)."""
        found: set[str] = set()
        found.update(self.locations.lookup(name, fuzzy=1.0))
        found.update(
            self.office.facility(f).location for f in self.facilities.lookup(name, fuzzy=1.0)
        )
        found.update(self.office.person(p).location for p in self.people.lookup(name, fuzzy=1.0))
        if not found:
            found.update(self.locations.lookup(name))
            found.update(self.office.facility(f).location for f in self.facilities.lookup(name))
            found.update(self.office.person(p).location for p in self.people.lookup(name))
        hint = (
            "Use a person's name (their desk), a facility ("
            + ", ".join(f.id for f in self.office.facilities)
            + ") or a location id."
        )
        universe = self.locations.keys() + self.facilities.keys() + self.people.keys()
        return self._one("place", name, sorted(found), hint, universe)

    def facility(self, name: str) -> str:
        hint = "Facilities: " + ", ".join(f.id for f in self.office.facilities) + "."
        return self._one(
            "facility", name, self.facilities.lookup(name), hint, self.facilities.keys()
        )

    def item_type(self, name: str) -> str:
        hint = "Item types: " + ", ".join(t.id for t in self.office.item_types) + "."
        return self._one(
            "item type", name, self.item_types.lookup(name), hint, self.item_types.keys()
        )

    def item(self, name: str) -> str:
        """An item id ``type:person``: ``stapler:zhang``, "Zhang's stapler", "stapler of Zhang"."""
        text = name.strip()
        if ":" in text:
            type_part, _, owner_part = text.partition(":")
        elif m := re.match(r"^(.+?)(?:'s|’s|s')\s+(.+)$", text):
            owner_part, type_part = m.group(1), m.group(2)
        elif m := re.match(
            r"^(?:(?:a|an|the|some)\s+)?(.+?)\s+(?:of|from|for|belonging to)\s+(?:the\s+)?(.+)$",
            text,
            re.I,
        ):
            type_part, owner_part = m.group(1), m.group(2)
        else:
            raise UnknownNameError(
                "item",
                name,
                f"Item {name!r} does not say whose it is. Name items as 'type:person', "
                "e.g. 'stapler:zhang' or 'document:lee'.",
            )
        item_type = self.item_type(type_part)
        return f"{item_type}:{self._owner(item_type, owner_part)}"

    def _owner(self, item_type: str, name: str) -> str:
        """Whose an item is: a person, or for an item owned by nobody the facility that keeps
        it for anyone ("tape:cupboard", "the tape from the stationery cupboard")."""
        try:
            return self.person(name)
        except GroundingError:
            kept = [
                f for f in self.facilities.lookup(name, fuzzy=1.0) if self._supplies(f, item_type)
            ]
            if len(kept) == 1:
                return kept[0]
            raise

    def _supplies(self, facility: str, item_type: str) -> bool:
        return self.office.facility(facility).supply(item_type) is not None

    def holder(self, name: str) -> str:
        """Who or what holds an item: ``locker`` (the robot's), else a person id, else a
        location id. Only an exact name of the locker is the locker: a typo of it is no guess."""
        if self.lockers.lookup(name, fuzzy=1.0):
            return LOCKER
        try:
            return self.person(name)
        except GroundingError:
            return self.place(name)

    # -- whole actions and updates -------------------------------------------------------
    def ground(self, action: Action) -> Action:
        """The same action with every name replaced by its id; raises GroundingError."""
        match action:
            case Inform():
                return action.model_copy(update={"contact": self.contact(action.contact)[1]})
            case Inquire():
                return action.model_copy(update={"contact": self.contact(action.contact)[1]})
            case ForwardFile():
                source = self.person(action.source)
                target = self.contact(action.target)[1]
                # the office names its file type as it likes ("script:ann", "drawing:bo")
                file = self.item(action.file) if action.file else self.office.file_of(source)
                file_type = self.office.file_type()
                if file_type is None:
                    raise UnknownNameError(
                        "file", file, "This office keeps no electronic files to forward."
                    )
                if self.office.item_type(file.partition(":")[0]).kind != "electronic":
                    raise UnknownNameError(
                        "file",
                        file,
                        f"{file!r} is not an electronic file; use '{file_type}:<person>'.",
                    )
                return action.model_copy(update={"source": source, "target": target, "file": file})
            case SendQR():
                return action.model_copy(
                    update={"contact": self.person(action.contact), "item": self.item(action.item)}
                )
            case Move():
                return action.model_copy(update={"place": self.place(action.place)})
            case WaitInPlace():
                return action.model_copy(update={"person": self.person(action.person)})
            case Wait() | Stop():
                return action
        raise TypeError(f"unknown action {action!r}")  # pragma: no cover

    def ground_update(self, update: MemoryUpdate) -> MemoryUpdate:
        """The same memory update with every name replaced by its id; raises GroundingError."""
        if isinstance(update, AvailabilityUpdate):
            return update.model_copy(update={"person": self.person(update.person)})
        if isinstance(update, OwnershipUpdate):
            return update.model_copy(
                update={
                    "person": self.person(update.person),
                    "item_type": self.item_type(update.item_type),
                }
            )
        if isinstance(update, ItemLocationUpdate):
            return update.model_copy(
                update={"item": self.item(update.item), "holder": self.holder(update.holder)}
            )
        raise TypeError(f"unknown memory update {update!r}")  # pragma: no cover

    def ground_milestone(self, milestone: Milestone) -> Milestone:
        """A goal milestone (``{"holds": ["Lee", "Zhang's stapler"]}``) with every name replaced
        by its id, as the simulator's truth is keyed; raises GroundingError or ValueError."""
        name, args = parse_milestone(milestone)
        grounded = [self._milestone_arg(arg) for arg in args]
        return {name: grounded if len(grounded) > 1 else grounded[0]}

    def _milestone_arg(self, arg: str) -> str:
        """A person, or an item (``type:owner``, ``type:*`` any of that type, or in words)."""
        type_part, colon, owner = arg.partition(":")
        if colon and owner.strip() == "*":
            return f"{self.item_type(type_part)}:*"
        if colon or re.search(r"'s\s|’s\s|s'\s|\s(?:of|from|for)\s", arg):
            return self.item(arg)
        return self.person(arg)

    # -- errors --------------------------------------------------------------------------
    def _one(
        self,
        kind: str,
        name: str,
        found: list[str],
        hint: str,
        universe: list[str] | None = None,
    ) -> str:
        """The one id found; else an error whose suggestions are only of the kind asked for
        (``universe``, the names of that kind), so an unknown person is never offered a room."""
        if len(found) == 1:
            return found[0]
        if found:
            raise AmbiguousNameError(
                kind,
                name,
                f"The {kind} {name!r} is ambiguous: it matches {', '.join(found)}. "
                "Use one of these ids.",
                found,
            )
        if universe is None:
            universe = (
                self.people.keys()
                + self.groups.keys()
                + self.facilities.keys()
                + self.locations.keys()
                + self.item_types.keys()
            )
        close = difflib.get_close_matches(normalize(name), universe, n=3, cutoff=0.6)
        maybe = f" Did you mean {', '.join(repr(c) for c in close)}?" if close else ""
        raise UnknownNameError(kind, name, f"Unknown {kind} {name!r}.{maybe} {hint}".strip())

    def _people_hint(self) -> str:
        hint = self._hints[0]
        if hint is None:  # built once: every lookup passes it along
            hint = self._hints[0] = "Known people: " + _listing([p.id for p in self.office.people])
        return hint

    def _groups_hint(self) -> str:
        hint = self._hints[1]
        if hint is None:
            hint = self._hints[1] = "Group chats: " + _listing([g.id for g in self.office.groups])
        return hint


def _as_written(name: str) -> str:
    return " ".join(name.casefold().split())


HINT_NAMES = 40  # names listed in an error's hint; a large office lists the first ones


def _listing(ids: list[str]) -> str:
    if len(ids) <= HINT_NAMES:
        return ", ".join(ids) + "."
    return ", ".join(ids[:HINT_NAMES]) + f" and {len(ids) - HINT_NAMES} more."
