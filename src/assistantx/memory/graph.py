"""Long-term memory: the assistant's belief about the office as an undirected graph
(``memory/belief_graph.py``).

Node ids are typed: ``person:zhang``, ``location:desk_04``, ``facility:printer``,
``item:stapler:zhang``, ``group:office_work``. Edges carry a ``rel``: ``at`` (person/facility →
location), ``owns`` (person → item), ``member`` (person → group), ``guards`` (person → facility).
The graph starts from the office's *known* facts; updates come from observations, each
recorded with its time and evidence.

Evidence is aged so memory stays flat over months of use: the graph itself holds one value per
fact, ``latest`` keeps the newest applied update per fact (one per person's availability, per
person and item type, per item's holder — bounded by the office, not by time), and ``updates``
keeps only the most recent ``history`` applied updates. The full list lives in the journal's
``memory_updates`` table, where the service writes each update as it happens.
"""

from __future__ import annotations

import json
from collections import deque
from typing import Any, Literal

from pydantic import TypeAdapter

from assistantx.core.office import Office
from assistantx.memory.belief_graph import BeliefGraph
from assistantx.memory.updates import (
    AppliedUpdate,
    AvailabilityUpdate,
    MemoryUpdate,
    OwnershipUpdate,
)

Availability = Literal["available", "unavailable", "unknown"]
LOCKER = "locker"

_applied_list: TypeAdapter[list[AppliedUpdate]] = TypeAdapter(list[AppliedUpdate])
HISTORY = 200  # applied updates kept in memory beyond the latest one per fact


def fact_key(update: MemoryUpdate) -> str:
    """The fact an update is about: later updates of the same fact supersede it."""
    if isinstance(update, AvailabilityUpdate):
        return f"availability:{update.person}"
    if isinstance(update, OwnershipUpdate):
        return f"ownership:{update.person}:{update.item_type}"
    return f"holder:{update.item}"


def pid(person_id: str) -> str:
    return f"person:{person_id}"


def lid(location_id: str) -> str:
    return f"location:{location_id}"


def fid(facility_id: str) -> str:
    return f"facility:{facility_id}"


def gid(group_id: str) -> str:
    return f"group:{group_id}"


def iid(item_id: str) -> str:
    return f"item:{item_id}"


def _bare(node: str) -> str:
    return node.split(":", 1)[1]


class LongTermMemory:
    """Typed queries and updates over the belief graph."""

    def __init__(
        self, office: Office, graph: BeliefGraph | None = None, *, history: int = HISTORY
    ) -> None:
        self.office = office
        self.graph: BeliefGraph = graph if graph is not None else _graph_from_office(office)
        self.updates: deque[AppliedUpdate] = deque(maxlen=history)  # newest last
        self.latest: dict[str, AppliedUpdate] = {}  # fact key -> the newest update of it
        self.applied_total = 0  # every update applied since the graph was built
        # Indexes kept beside the graph so a query costs what its answer costs, not a scan
        # of a 1,024-person office: item type -> known owners / people known to lack one.
        self._owners: dict[str, set[str]] = {}
        self._lacking: dict[str, set[str]] = {}
        for node, data in self.graph.nodes(data=True):
            if data["kind"] == "item" and data.get("owner"):
                self._owners.setdefault(data["type"], set()).add(data["owner"])
            elif data["kind"] == "person":
                for item_type in data["lacks"]:
                    self._lacking.setdefault(item_type, set()).add(_bare(node))

    # -- queries -------------------------------------------------------------------------
    def availability(self, person_id: str) -> Availability:
        value: Availability = self.graph.nodes[pid(person_id)]["available"]
        return value

    def availability_observed_at(self, person_id: str) -> float | None:
        value: float | None = self.graph.nodes[pid(person_id)].get("observed_at")
        return value

    def people(self) -> list[str]:
        return [p.id for p in self.office.people]

    def available_people(self) -> list[str]:
        return [p for p in self.people() if self.availability(p) == "available"]

    def location_of(self, person_id: str) -> str:
        return self._neighbour(pid(person_id), "at", "location")

    def facility_location(self, facility_id: str) -> str:
        return self._neighbour(fid(facility_id), "at", "location")

    def people_at(self, location_id: str) -> list[str]:
        return sorted(
            _bare(n)
            for n in self.graph.neighbors(lid(location_id))
            if self.graph.nodes[n]["kind"] == "person"
        )

    def guards(self, facility_id: str) -> list[str]:
        return self._neighbours(fid(facility_id), "guards", "person")

    def guarded_by(self, person_id: str) -> list[str]:
        return self._neighbours(pid(person_id), "guards", "facility")

    def members(self, group_id: str) -> list[str]:
        return self._neighbours(gid(group_id), "member", "person")

    def groups_of(self, person_id: str) -> list[str]:
        return self._neighbours(pid(person_id), "member", "group")

    def owners(self, item_type: str) -> list[str]:
        """People known to own an item of this type."""
        return sorted(self._owners.get(item_type, ()))

    def lenders(self, item_type: str) -> list[str]:
        """Owners of an item of this type that memory does not know to be elsewhere: the
        people who can hand one over now (an owner whose item someone else holds cannot)."""
        return [p for p in self.owners(item_type) if self.lent_out(p, item_type) is None]

    def lent_out(self, person_id: str, item_type: str) -> str | None:
        """The other person who holds ``person_id``'s item of this type, when memory knows
        one does (from a hand-over); None when it is with its owner, on its way (in the
        locker) or unknown."""
        holder = self.item_holder(f"{item_type}:{person_id}")
        if holder is None or holder == person_id or not self.graph.has_node(pid(holder)):
            return None
        return holder

    def taken_by_another(self, item_id: str, instruction_id: str) -> AppliedUpdate | None:
        """The hand-over that took ``item_id`` away from its owner (into a locker or to
        someone else), when another instruction than ``instruction_id`` made it; None when
        the item is with its owner, not known to have moved, or moved by this instruction."""
        holder = self.item_holder(item_id)
        owner = item_id.partition(":")[2]
        moved = self.latest.get(f"holder:{item_id}")
        if holder is None or holder == owner or moved is None:
            return None
        return moved if moved.instruction_id != instruction_id else None

    def known_not_owners(self, item_type: str) -> list[str]:
        return sorted(self._lacking.get(item_type, ()))

    def known_not_owners_of(self, person_id: str) -> list[str]:
        return sorted(self.graph.nodes[pid(person_id)]["lacks"])

    def ownership(self, person_id: str, item_type: str) -> bool | None:
        """True/False when known, None when memory does not know."""
        if self.graph.has_node(iid(f"{item_type}:{person_id}")):
            return True
        if item_type in self.graph.nodes[pid(person_id)]["lacks"]:
            return False
        return None

    def items_of(self, person_id: str) -> list[str]:
        return self._neighbours(pid(person_id), "owns", "item")

    def item_holder(self, item_id: str) -> str | None:
        node = iid(item_id)
        if not self.graph.has_node(node):
            return None
        holder: str | None = self.graph.nodes[node].get("holder")
        return holder

    def has_item(self, item_id: str) -> bool:
        return bool(self.graph.has_node(iid(item_id)))

    def _neighbours(self, node: str, rel: str, kind: str) -> list[str]:
        return sorted(
            _bare(n)
            for n in self.graph.neighbors(node)
            if self.graph.edges[node, n]["rel"] == rel and self.graph.nodes[n]["kind"] == kind
        )

    def _neighbour(self, node: str, rel: str, kind: str) -> str:
        found = self._neighbours(node, rel, kind)
        if len(found) != 1:
            raise KeyError(f"{node} has {len(found)} {rel} {kind} neighbours")
        return found[0]

    # -- updates -------------------------------------------------------------------------
    def apply(
        self, update: MemoryUpdate, time: float, instruction_id: str | None = None
    ) -> AppliedUpdate:
        """Apply a typed update (ids already resolved) and record it with its evidence."""
        if isinstance(update, AvailabilityUpdate):
            changed = self._set_availability(update.person, update.available, time)
        elif isinstance(update, OwnershipUpdate):
            changed = self._set_ownership(update.person, update.item_type, update.owns)
        else:
            changed = self._set_holder(update.item, update.holder)
        applied = AppliedUpdate(
            time=time, instruction_id=instruction_id, update=update, changed=changed
        )
        self.updates.append(applied)
        self.latest[fact_key(update)] = applied
        self.applied_total += 1
        return applied

    def _set_availability(self, person_id: str, available: bool | None, time: float) -> bool:
        node = self.graph.nodes[pid(person_id)]
        value: Availability = (
            "unknown" if available is None else "available" if available else "unavailable"
        )
        changed = bool(node["available"] != value)
        node["available"] = value
        node["observed_at"] = time
        return changed

    def _set_ownership(self, person_id: str, item_type: str, owns: bool) -> bool:
        self.office.person(person_id)
        self.office.item_type(item_type)
        node = iid(f"{item_type}:{person_id}")
        lacks: set[str] = self.graph.nodes[pid(person_id)]["lacks"]
        if owns:
            lacks.discard(item_type)
            self._lacking.get(item_type, set()).discard(person_id)
            if self.graph.has_node(node):
                return False
            self._add_item(person_id, item_type)
            return True
        if self.lent_out(person_id, item_type) is not None:
            # "I don't have it" from someone whose item memory knows is elsewhere (lent, in
            # the locker) is about where the item is, not who owns it: ownership stays.
            return False
        changed = bool(item_type not in lacks or self.graph.has_node(node))
        lacks.add(item_type)
        self._lacking.setdefault(item_type, set()).add(person_id)
        if self.graph.has_node(node):
            if self.graph.nodes[node].get("owner"):
                self._owners.get(item_type, set()).discard(person_id)
            self.graph.remove_node(node)
        return changed

    def _set_holder(self, item_id: str, holder: str) -> bool:
        node = iid(item_id)
        if not self.graph.has_node(node):
            item_type, _, owner = item_id.partition(":")
            self.office.item_type(item_type)
            self.graph.add_node(node, kind="item", type=item_type, owner=None, holder=None)
            if owner and self.graph.has_node(pid(owner)):
                self.graph.nodes[node]["for"] = owner
        changed = bool(self.graph.nodes[node].get("holder") != holder)
        self.graph.nodes[node]["holder"] = holder
        return changed

    def _add_item(self, person_id: str, item_type: str) -> None:
        node = iid(f"{item_type}:{person_id}")
        self.graph.add_node(node, kind="item", type=item_type, owner=person_id, holder=person_id)
        self.graph.add_edge(pid(person_id), node, rel="owns")
        self._owners.setdefault(item_type, set()).add(person_id)

    # -- persistence ---------------------------------------------------------------------
    def snapshot(self) -> dict[str, Any]:
        """The graph, the latest update per fact and the recent history (all bounded)."""
        data = self.graph.node_link_data()
        for node in data["nodes"]:
            if "lacks" in node:
                node["lacks"] = sorted(node["lacks"])
        return {
            "graph": data,
            "updates": [u.model_dump(mode="json") for u in self.updates],
            "latest": [u.model_dump(mode="json") for u in self.latest.values()],
            "applied_total": self.applied_total,
        }

    @classmethod
    def restore(cls, office: Office, snapshot: dict[str, Any]) -> LongTermMemory:
        data = json.loads(json.dumps(snapshot["graph"]))
        for node in data["nodes"]:
            if "lacks" in node:
                node["lacks"] = set(node["lacks"])
        graph = BeliefGraph.from_node_link_data(data)
        memory = cls(office, graph)
        history = _applied_list.validate_python(snapshot.get("updates", []))
        memory.updates.extend(history)
        # Snapshots written before ``latest`` existed: their history holds every update.
        for applied in _applied_list.validate_python(snapshot.get("latest", [])) or history:
            memory.latest[fact_key(applied.update)] = applied
        memory.applied_total = int(snapshot.get("applied_total", len(history)))
        return memory

    def replay(self, applied: AppliedUpdate) -> None:
        """Apply a journaled update again (one written after the snapshot restored from)."""
        self.apply(applied.update, applied.time, applied.instruction_id)


def _graph_from_office(office: Office) -> BeliefGraph:
    g = BeliefGraph()
    for loc in office.locations:
        g.add_node(lid(loc.id), kind="location", name=loc.name, type=loc.kind)
    for f in office.facilities:
        g.add_node(fid(f.id), kind="facility", name=f.name)
        g.add_edge(fid(f.id), lid(f.location), rel="at")
    for p in office.people:
        g.add_node(pid(p.id), kind="person", name=p.name, available="unknown", lacks=set())
        g.add_edge(pid(p.id), lid(p.location), rel="at")
        for o in p.owns:
            if o.known:
                node = iid(p.item_id(o.type))
                g.add_node(node, kind="item", type=o.type, owner=p.id, holder=p.id)
                g.add_edge(pid(p.id), node, rel="owns")
    for f in office.facilities:
        for guard in f.guards:
            g.add_edge(pid(guard), fid(f.id), rel="guards")
    for grp in office.groups:
        g.add_node(gid(grp.id), kind="group", name=grp.name)
        for m in grp.members:
            g.add_edge(pid(m), gid(grp.id), rel="member")
    return g
