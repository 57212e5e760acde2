"""The office: locations, people, items, facilities and group chats, loaded from YAML.

The office file is the ground truth of who works where and who owns what. Each ownership
fact says whether the assistant *knows* it at start; the Memory Unit is built from the known
facts only, the simulator from all of them.

Item ids are ``"<type>:<owner>"`` (``"stapler:zhang"``), so an item is named by its type and
its owner, as people name them ("Zhang's stapler").
"""

from __future__ import annotations

import logging
import math
from collections import Counter
from functools import cached_property
from pathlib import Path
from typing import Any, Literal, NewType, TypeVar

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from assistantx.core import office_upgrade
from assistantx.core.errors import OfficeError
from assistantx.core.yaml_file import read_yaml

logger = logging.getLogger(__name__)

DEFAULT_OFFICE = Path(__file__).resolve().parents[1] / "data" / "dataset" / "office.yaml"

PersonId = NewType("PersonId", str)
"""The id of a person of the office, resolved once from a name at the edge (the API route, the
command line, an inbound message, the dataset); below the edge nobody resolves it again."""

LocationKind = Literal["workstation", "facility", "room"]
# How an operation works, from what it takes and what it makes (see Operation.shape).
OperationShape = Literal["make", "render", "transform", "treat", "use"]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Location(_Model):
    id: str
    kind: LocationKind
    name: str
    x: float = Field(description="metres, map frame")
    y: float = Field(description="metres, map frame")


ItemKind = Literal["belonging", "personal", "electronic", "product"]
# The properties of an item type that kinds of task ask for (task_kinds: what a kind works
# on, the tool its doer needs), instead of type ids: a paper one signs, a seal, a file.
ItemProperty = Literal["signable", "seals", "electronic"]


# The plain word for a person's electronic file, whatever id the office gives its type
# ("script", "drawing"): a messenger that cannot know the office names a file a person sent
# ``file:<person>`` (ports.messenger.persons_file), and the resolver reads the word as the
# office's type.
FILE_WORD = "file"


class ItemType(_Model):
    """A kind of item.

    ``belonging``: shareable, anyone's will do (a stapler); ``personal``: only the owner's
    will do (a document, a lunch); ``electronic``: a file, forwarded rather than carried;
    ``product``: made by a facility (a coffee, a printout), owned by nobody at start.
    """

    id: str
    name: str
    synonyms: tuple[str, ...] = ()
    kind: ItemKind = "belonging"
    purposes: tuple[str, ...] = Field(
        default=(), description="verbs it is for: 'cut' (scissors), 'write' (pen)"
    )
    signable: bool = Field(
        default=False, description="a paper a person signs or stamps (a document, a form)"
    )
    seals: bool = Field(
        default=False, description="the tool that stamps a signable paper (a company seal)"
    )
    consumable: bool = Field(
        default=False, description="used up when used (paper, wipes): one is given, not lent"
    )
    mass: bool = Field(
        default=False,
        description="named as stuff, not as a thing: 'some gaffer tape', never 'a gaffer "
        "tape' (a noun the dictionary knows only as stuff, glue or ink, needs no mark)",
    )

    @property
    def physical(self) -> bool:
        return self.kind != "electronic"

    @property
    def electronic(self) -> bool:
        return self.kind == "electronic"


class Operation(_Model):
    """Something a facility does, declared by the office (print, boil, scan, mail ...).

    ``verbs`` are the words that ask for it; ``input`` the item type it works on (none: it
    makes something from nothing the requester gives); ``product`` the item type it makes
    (none: the input comes back changed, e.g. heated). The facilities that list it offer it,
    and their guards run it.
    """

    id: str
    name: str = Field(description="how a person names it, e.g. 'print'")
    verbs: tuple[str, ...] = ()
    input: str | None = None
    product: str | None = None
    consumes: bool = Field(
        default=False,
        description="the item it works on does not come back (a shredder): the requester is "
        "told it was done, nothing is handed back",
    )
    sends_out: bool = Field(
        default=False,
        description="it sends the item to someone outside the office (a fax to a tax office): "
        "nothing comes back; the requester is told where it went",
    )
    destination_asked: str = Field(
        default="the name of the place",
        description="what a requester who did not say where it goes is asked for, in words "
        "that fit how it sends: 'the fax number' for a fax, 'the name and address of the "
        "place' for a courier (only for an operation that sends out)",
    )
    done: str | None = Field(
        default=None,
        description="what it did to an item, as told to people ('scanned to PDF'); default: "
        "the past participle of its name's verb ('shredded', 'faxed')",
    )

    @property
    def request_phrases(self) -> tuple[str, ...]:
        """The phrases whose first word asks for it: its verbs. Its name is a display label
        ("print spine labels" may name a label run whose verb is "label"), read as a verb
        only where the office declares no verbs ("hold a meeting")."""
        return self.verbs or (self.name,)

    @property
    def returns_item(self) -> bool:
        """Whether the item it works on comes back to be collected (not shredded, not sent
        outside)."""
        return not (self.consumes or self.sends_out)

    def shape(self, office: Office) -> OperationShape:
        """``make``: a product from nothing (coffee); ``render``: a product from a file
        (a printout); ``transform``: a product from a physical item (a copy); ``treat``: the
        item comes back changed (heated); ``use``: neither (a meeting room)."""
        if self.input is None:
            return "make" if self.product else "use"
        if office.item_type(self.input).kind == "electronic":
            return "render" if self.product else "use"
        return "transform" if self.product else "treat"


class Ownership(_Model):
    type: str
    known: bool = True
    at: str | None = Field(default=None, description="location where it is kept, if not the desk")
    facility: str | None = Field(
        default=None, description="the facility at ``at`` that keeps it, when several stand there"
    )


class Person(_Model):
    id: str
    name: str
    aliases: tuple[str, ...] = ()
    location: str
    handle: str
    owns: tuple[Ownership, ...] = ()

    def item_id(self, type_id: str) -> str:
        return f"{type_id}:{self.id}"


class Supply(_Model):
    """Items owned by nobody, kept at a facility for anyone (pens in a stationery cupboard).

    Its item id is ``"<type>:<facility>"``; taking one needs no one's yes, only the keeper who
    takes it out. ``count``: how many there are; None (the default): taking one does not empty
    the place (a box of pens is refilled before anyone notices)."""

    type: str
    count: int | None = Field(default=None, ge=0)


class Facility(_Model):
    id: str
    name: str
    synonyms: tuple[str, ...] = ()
    location: str
    operations: tuple[str, ...] = Field(default=(), description="ids of operations it offers")
    guards: tuple[str, ...] = Field(default=(), description="people who run it or sit next to it")
    products: tuple[str, ...] = Field(default=(), description="what it makes, e.g. coffee")
    supplies: tuple[Supply, ...] = Field(
        default=(), description="items owned by nobody kept here for anyone (pens, tape)"
    )

    def supply(self, type_id: str) -> Supply | None:
        return next((s for s in self.supplies if s.type == type_id), None)

    def item_id(self, type_id: str) -> str:
        return f"{type_id}:{self.id}"


class Group(_Model):
    id: str
    name: str
    members: tuple[str, ...]


class Robot(_Model):
    home: str
    speed_mps: float = 0.5


class Office(_Model):
    name: str
    locations: tuple[Location, ...]
    item_types: tuple[ItemType, ...]
    people: tuple[Person, ...]
    facilities: tuple[Facility, ...]
    groups: tuple[Group, ...]
    robot: Robot
    operations: tuple[Operation, ...] = ()

    @cached_property
    def _index(self) -> dict[str, Any]:
        """Id indexes per kind, filled on first use (a plain dict: pydantic private
        attributes cost a slow ``__getattr__`` on every lookup)."""
        return {}

    # -- lookups -----------------------------------------------------------------------
    def location(self, location_id: str) -> Location:
        return _by_id(self.locations, self._index, location_id, "location")

    def person(self, person_id: str) -> Person:
        return _by_id(self.people, self._index, person_id, "person")

    def facility(self, facility_id: str) -> Facility:
        return _by_id(self.facilities, self._index, facility_id, "facility")

    def group(self, group_id: str) -> Group:
        return _by_id(self.groups, self._index, group_id, "group")

    def item_type(self, type_id: str) -> ItemType:
        return _by_id(self.item_types, self._index, type_id, "item type")

    def operation(self, operation_id: str) -> Operation:
        return _by_id(self.operations, self._index, operation_id, "operation")

    def offering(self, operation_id: str) -> list[Facility]:
        """The facilities that offer an operation (several may, even at one location)."""
        return [f for f in self.facilities if operation_id in f.operations]

    def making(self, product: str) -> Operation | None:
        """The operation whose product is ``product`` (a coffee → the coffee operation)."""
        return next((o for o in self.operations if o.product == product), None)

    def made_from(self, input_type: str) -> str | None:
        """The product an operation makes from an item of ``input_type`` while keeping the
        original (a copy of a document): the item that joins the original in the locker."""
        return next(
            (
                o.product
                for o in self.operations
                if o.input == input_type and o.product and o.shape(self) == "transform"
            ),
            None,
        )

    def with_shape(self, shape: OperationShape) -> list[Operation]:
        return [o for o in self.operations if o.shape(self) == shape]

    def runnable(self, operation_id: str) -> bool:
        """Whether the assistant can run it on someone's behalf (not just a room to use)."""
        return self.operation(operation_id).shape(self) != "use"

    def keeper(self, owner: str, type_id: str) -> Facility | None:
        """The facility where ``owner``'s item is kept (a fridge, a cupboard), if not on them;
        for an item owned by nobody (``owner`` is the facility keeping it), that facility."""
        if self.is_supply(f"{type_id}:{owner}"):
            return self.facility(owner)
        own = next((o for o in self.person(owner).owns if o.type == type_id), None)
        if own is None or own.at is None:
            return None
        if own.facility is not None:
            return self.facility(own.facility)
        here = [f for f in self.facilities if f.location == own.at]
        return here[0] if len(here) == 1 else None

    # -- item types by property ---------------------------------------------------------
    def type_with(self, prop: ItemProperty) -> str | None:
        """The office's item type that has ``prop`` (its signable paper, its seal, its file)."""
        return next((t.id for t in self.item_types if getattr(t, prop)), None)

    def signable_type(self) -> str | None:
        """The item type a person signs or stamps (the office's ``signable`` paper)."""
        return next((t.id for t in self.item_types if t.signable), None)

    def seal_tool(self) -> str | None:
        """The item type that stamps a signable paper (the office's ``seals`` tool)."""
        return next((t.id for t in self.item_types if t.seals), None)

    def file_type(self) -> str | None:
        """The office's electronic file type (what is forwarded and printed)."""
        return next((t.id for t in self.item_types if t.electronic), None)

    def file_of(self, person: str, type_id: str | None = None) -> str:
        """The item id of ``person``'s file, whatever this office calls its electronic type
        ("rota:ann", "log:bram"; ``file:…`` where the office has none); ``type_id``: one of
        the office's electronic types named ("my slides" where slides are a type of their
        own beside the generic file), that one rather than the first."""
        if type_id is not None and any(t.id == type_id and t.electronic for t in self.item_types):
            return f"{type_id}:{person}"
        return f"{self.file_type() or FILE_WORD}:{person}"

    # -- items owned by nobody ------------------------------------------------------------
    def is_person(self, person_id: str) -> bool:
        try:
            self.person(person_id)
        except KeyError:
            return False
        return True

    def is_supply(self, item_id: str) -> bool:
        """Whether ``item_id`` (``type:holder``) is one of a facility's supplies, owned by
        nobody: it leaves with no one's yes."""
        type_id, _, holder = item_id.partition(":")
        try:
            facility = self.facility(holder)
        except KeyError:
            return False
        return facility.supply(type_id) is not None

    def supplier(self, type_id: str) -> Facility | None:
        """The facility that keeps ``type_id`` for anyone (the stationery cupboard's pens);
        one whose count is 0 has none to give."""

        def has(f: Facility) -> bool:
            supply = f.supply(type_id)
            return supply is not None and supply.count != 0

        return next((f for f in self.facilities if has(f)), None)

    def owner_name(self, owner: str) -> str | None:
        """A person's name, None for an item owned by nobody (its owner part a facility)."""
        return self.person(owner).name if self.is_person(owner) else None

    def kept_owner(self, type_id: str, *, besides: str | None = None) -> str | None:
        """The item of ``type_id`` to use when nobody's is named: the office's supply kept
        for anyone (its id part is the facility: no one's yes needed), else whose belonging is
        kept at a facility (a label maker in the stationery cupboard), fetched by the keeper
        with its owner's yes. None for personal items (nobody asks for "a lunch")."""
        supplier = self.supplier(type_id)
        if supplier is not None:
            return supplier.id
        if self.item_type(type_id).kind != "belonging":
            return None
        return next(
            (
                p.id
                for p in self.people
                if p.id != besides
                and any(o.type == type_id for o in p.owns)
                and self.keeper(p.id, type_id) is not None
            ),
            None,
        )

    def place_names(self) -> dict[str, str]:
        """Every name of a place, lower case → its location id: the locations by name and id
        words, and each facility's names at its location ("the stationery cupboard", "the
        supply room"), for the reader's lexicon."""
        names: dict[str, str] = {}
        for loc in self.locations:
            for name in (loc.name, loc.id.replace("_", " ")):
                names.setdefault(name.lower(), loc.id)
        for f in self.facilities:
            for name in (f.name, *f.synonyms):
                names.setdefault(name.lower(), f.location)
        return names

    def workstations(self) -> list[Location]:
        return [loc for loc in self.locations if loc.kind == "workstation"]

    def public_places(self) -> list[Location]:
        return [loc for loc in self.locations if loc.kind != "workstation"]

    def owners_of(self, type_id: str, *, known_only: bool = False) -> list[str]:
        return [
            p.id
            for p in self.people
            for o in p.owns
            if o.type == type_id and (o.known or not known_only)
        ]

    def distance(self, a: str, b: str) -> float:
        """Straight-line distance in metres between two locations (the map gives paths)."""
        la, lb = self.location(a), self.location(b)
        return math.hypot(la.x - lb.x, la.y - lb.y)


_T = TypeVar("_T", Location, Person, Facility, Group, ItemType, Operation)


def _by_id(entries: tuple[_T, ...], index: dict[str, Any], entry_id: str, kind: str) -> _T:
    # An id index per kind, built on first use: a 1,024-person office is looked up by id
    # tens of thousands of times per instruction, and a scan made that quadratic. Keyed to
    # the tuple itself, so a copy with other entries (``model_copy(update=...)``) rebuilds.
    held = index.get(kind)
    if held is None or held[0] is not entries:
        held = index[kind] = (entries, {e.id: e for e in entries})
    found: _T | None = held[1].get(entry_id)
    if found is None:
        raise KeyError(f"unknown {kind} {entry_id!r}")
    return found


def load_office(path: str | Path | None = None) -> Office:
    """Load and check an office file; any problem raises OfficeError naming file and entry."""
    file = Path(path) if path is not None else DEFAULT_OFFICE
    where = str(file)
    raw = read_yaml(file, lambda why: OfficeError(where, "file", why))
    return parse_office(raw, where)


def parse_office(raw: Any, where: str = "<office>") -> Office:
    if not isinstance(raw, dict):
        raise OfficeError(where, "file", "must be a mapping with locations, people, ...")
    raw, notes = office_upgrade.upgrade(raw)
    for note in notes:  # a file of the previous format: `assistantx office migrate` updates it
        logger.warning("%s: previous office format: %s", where, note)
    try:
        office = Office.model_validate(raw)
    except ValidationError as exc:
        err = exc.errors()[0]
        raise OfficeError(where, _entry_name(raw, err["loc"]), err["msg"]) from exc
    _check_references(office, where)
    for clash in contact_clashes(office):
        logger.warning("%s: %s", where, clash)
    return office


def contact_clashes(office: Office) -> list[str]:
    """A person's name or alias written exactly like a group's id or name: a message to
    that spelling is ambiguous (an id still means its own group). One line each, naming
    both, for the office's author."""
    groups: dict[str, list[str]] = {}
    for g in office.groups:
        for spelling in {g.id, g.id.replace("_", " "), g.name}:
            groups.setdefault(" ".join(spelling.casefold().split()), []).append(g.id)
    found: list[str] = []
    for p in office.people:
        for spelling in dict.fromkeys((p.name, *p.aliases)):
            for group_id in groups.get(" ".join(spelling.casefold().split()), []):
                found.append(
                    f"person {p.id!r} is also called {spelling!r}, like group {group_id!r}: a "
                    f"message to {spelling!r} is ambiguous; address them by id, or rename one"
                )
    return found


def _entry_name(raw: dict[str, Any], loc: tuple[int | str, ...]) -> str:
    """Turn a pydantic error location into 'people[3] (zhang).owns[0].type'."""
    parts: list[str] = []
    node: Any = raw
    for key in loc:
        if isinstance(key, int):
            label = f"[{key}]"
            if isinstance(node, list) and key < len(node):
                node = node[key]
                if isinstance(node, dict) and "id" in node:
                    label += f" ({node['id']})"
            parts.append(label)
        else:
            parts.append(("." if parts else "") + key)
            node = node.get(key) if isinstance(node, dict) else None
    return "".join(parts) or "file"


def _check_references(office: Office, where: str) -> None:
    def fail(entry: str, problem: str) -> None:
        raise OfficeError(where, entry, problem)

    for section, entries in (
        ("locations", office.locations),
        ("item_types", office.item_types),
        ("people", office.people),
        ("facilities", office.facilities),
        ("groups", office.groups),
        ("operations", office.operations),
    ):
        counts = Counter(e.id for e in entries)
        for entry_id, n in counts.items():
            if n > 1:
                fail(f"{section} ({entry_id})", f"duplicate id {entry_id!r} ({n} entries)")
        for e in entries:
            if not e.id or not e.id.replace("_", "").isalnum() or e.id != e.id.lower():
                fail(f"{section} ({e.id})", "ids are lower-case letters, digits and '_'")

    location_ids = {loc.id for loc in office.locations}
    type_ids = {t.id for t in office.item_types}
    person_ids = {p.id for p in office.people}
    all_ids = [*location_ids, *person_ids, *(g.id for g in office.groups)]
    for entry_id, n in Counter(all_ids).items():
        if n > 1:
            fail(entry_id, "the same id names two different things (person/place/group)")
    for f in office.facilities:
        # A facility may share its id with the location it stands in, nothing else.
        if f.id in person_ids or f.id in {g.id for g in office.groups}:
            fail(f"facilities ({f.id})", "the id is already used by a person or group")
        if f.id in location_ids and f.id != f.location:
            fail(f"facilities ({f.id})", "the id names a different location")

    for p in office.people:
        if p.location not in location_ids:
            fail(f"people ({p.id}).location", f"unknown location {p.location!r}")
        seen: set[str] = set()
        for o in p.owns:
            if o.type not in type_ids:
                fail(f"people ({p.id}).owns", f"unknown item type {o.type!r}")
            if o.at is not None and o.at not in location_ids:
                fail(f"people ({p.id}).owns ({o.type}).at", f"unknown location {o.at!r}")
            if o.facility is not None:
                if o.facility not in {f.id for f in office.facilities}:
                    fail(f"people ({p.id}).owns ({o.type}).facility", f"unknown {o.facility!r}")
                if office.facility(o.facility).location != o.at:
                    fail(
                        f"people ({p.id}).owns ({o.type}).facility",
                        f"{o.facility!r} is not at {o.at!r}",
                    )
            elif o.at is not None:
                here = [f.id for f in office.facilities if f.location == o.at]
                if len(here) > 1:
                    fail(
                        f"people ({p.id}).owns ({o.type}).at",
                        f"several facilities at {o.at!r} ({', '.join(here)}): name one "
                        "under 'facility'",
                    )
            if o.type in seen:
                fail(f"people ({p.id}).owns", f"item type {o.type!r} listed twice")
            seen.add(o.type)
    for f in office.facilities:
        if f.location not in location_ids:
            fail(f"facilities ({f.id}).location", f"unknown location {f.location!r}")
        for supply in f.supplies:
            if supply.type not in type_ids:
                fail(f"facilities ({f.id}).supplies", f"unknown item type {supply.type!r}")
            kind = office.item_type(supply.type).kind
            if kind in ("electronic", "product"):
                fail(
                    f"facilities ({f.id}).supplies ({supply.type})",
                    f"a supply is a physical item kept here, not a {kind}",
                )
        if f.supplies and not f.guards:
            fail(f"facilities ({f.id}).supplies", "nobody guards it to take its supplies out")
        for g in f.guards:
            if g not in person_ids:
                fail(f"facilities ({f.id}).guards", f"unknown person {g!r}")
    operation_ids = {o.id for o in office.operations}
    for op_ in office.operations:
        for field_name, type_id in (("input", op_.input), ("product", op_.product)):
            if type_id is not None and type_id not in type_ids:
                fail(f"operations ({op_.id}).{field_name}", f"unknown item type {type_id!r}")
        if op_.product is not None and office.item_type(op_.product).kind not in (
            "product",
            "electronic",  # a file made from a paper (scan to PDF), sent by message
        ):
            fail(f"operations ({op_.id}).product", f"item type {op_.product!r} is not a product")
        if not office.offering(op_.id):
            fail(f"operations ({op_.id})", "no facility offers it")
    makers = Counter(op_.product for op_ in office.operations if op_.product)
    for product, n in makers.items():
        if n > 1:
            fail(f"operations (product {product})", f"{n} operations make {product!r}")
    for f in office.facilities:
        for op in f.operations:
            if op not in operation_ids:
                fail(
                    f"facilities ({f.id}).operations",
                    f"unknown operation {op!r} (declare it under 'operations')",
                )
        made = {office.operation(op).product for op in f.operations} - {None}
        for product in f.products:
            if product not in made:
                fail(f"facilities ({f.id}).products", f"no operation here makes {product!r}")
    for grp in office.groups:
        for m in grp.members:
            if m not in person_ids:
                fail(f"groups ({grp.id}).members", f"unknown person {m!r}")
    if office.robot.home not in location_ids:
        fail("robot.home", f"unknown location {office.robot.home!r}")
