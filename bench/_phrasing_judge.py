"""A phrasings file (docs/phrasings.md) and the judge of one run's trace against one case.

The file is read and checked against its office: a bad file is one ``PhrasingsError`` whose
message is one line. ``judge`` reads the trace that ``assistantx run --trace-out`` writes (a
``Trace`` dumped as JSON) and says what the run did (``got``), whether that meets what the
writer expected, and which wrong physical action it took, if any. Only actions that ran
(not refused by the runtime's guards) count.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from assistantx.core.errors import OfficeError
from assistantx.core.office import Office, load_office

Expect = Literal["deliver", "ask", "words", "decline"]
EXPECTS: tuple[Expect, ...] = ("deliver", "ask", "words", "decline")

# Actions that move the robot, open the locker or pass an item on: what a "physical step" is.
# A forwarded file is a hand-over although no wheel turns.
PHYSICAL = frozenset({"move", "send_qr", "wait_in_place", "forward_file"})
# Locker codes that only put an item in or take it out; the others run a service on it.
_CARRY = frozenset({"deposit", "collect"})
# Stop outcomes that say the task cannot be done.
_CANNOT = frozenset({"unachievable", "failed"})


class PhrasingsError(Exception):
    """A phrasings file that cannot be run; the message is one line."""


class Delivery(BaseModel):
    """One more hand-over a combination asks for ("take my rule to Heath, and a tea for me")."""

    model_config = ConfigDict(extra="forbid")

    recipient: str = Field(min_length=1)
    item: str = Field(min_length=1)


class Case(BaseModel):
    model_config = ConfigDict(extra="forbid", populate_by_name=True)

    id: str = Field(min_length=1)
    as_: str = Field(alias="as", min_length=1)
    text: str = Field(min_length=1)
    expect: Expect
    recipient: str | None = None
    item: str | None = None
    owner_asked: str | None = None
    also: tuple[Delivery, ...] = ()  # deliver: the combination's other hand-overs, each required
    accept: tuple[Expect, ...] = ()
    why: str = ""

    @model_validator(mode="after")
    def _deliver_names_what_and_whom(self) -> Case:
        if self.expect == "deliver" and (self.recipient is None or self.item is None):
            raise ValueError("a deliver case needs both recipient and item")
        if self.also and self.expect != "deliver":
            raise ValueError("only a deliver case has more deliveries (also)")
        return self


class Phrasings(BaseModel):
    model_config = ConfigDict(extra="forbid")

    office: str
    cases: list[Case] = Field(min_length=1)


def load_phrasings(
    path: Path, office_override: str | None = None
) -> tuple[Phrasings, Office, Path]:
    """The file's cases, its office and the office file's path (relative to the YAML file),
    checked: unique ids, every person id known to the office, every item known."""
    try:
        raw = yaml.safe_load(path.read_text())
    except (OSError, yaml.YAMLError) as exc:
        raise PhrasingsError(f"cannot read {path}: {_one_line(str(exc))}") from exc
    try:
        phrasings = Phrasings.model_validate(raw)
    except ValidationError as exc:
        raise PhrasingsError(f"{path}: {_where(raw, exc)}") from exc
    office_path = Path(office_override or path.parent / phrasings.office)
    try:
        office = load_office(office_path)
    except (OfficeError, OSError) as exc:
        raise PhrasingsError(f"{path}: office {office_path}: {_one_line(str(exc))}") from exc
    seen: set[str] = set()
    for case in phrasings.cases:
        if case.id in seen:
            raise PhrasingsError(f"{path}: case {case.id}: id used twice")
        seen.add(case.id)
        for field in ("as_", "recipient", "owner_asked"):
            person = getattr(case, field)
            if person is not None and not office.is_person(person):
                name = field.rstrip("_")
                raise PhrasingsError(
                    f"{path}: case {case.id}: {name}: {person!r} is no person id of the office"
                )
        for more in case.also:
            if not office.is_person(more.recipient):
                raise PhrasingsError(
                    f"{path}: case {case.id}: also: {more.recipient!r} is no person id "
                    "of the office"
                )
            if not known_item(office, more.item):
                raise PhrasingsError(
                    f"{path}: case {case.id}: also: {more.item!r} is no item id, item type or "
                    "product of the office"
                )
        if case.item is not None and not known_item(office, case.item):
            raise PhrasingsError(
                f"{path}: case {case.id}: item: {case.item!r} is no item id, item type or "
                "product of the office"
            )
    return phrasings, office, office_path


def known_item(office: Office, item: str) -> bool:
    """An item id (``type:holder``), an item type id or a facility's product type."""
    type_id, colon, holder = item.partition(":")
    types = {t.id for t in office.item_types} | {p for f in office.facilities for p in f.products}
    if not colon:
        return type_id in types
    holders = {p.id for p in office.people} | {f.id for f in office.facilities}
    return type_id in types and holder in holders


def truth_goal(case: Case) -> list[dict[str, list[str]]] | None:
    """What the requester of a deliver case really wants, as goal milestones (``holds``: the
    recipient holds the item, and each hand-over under ``also``), so the simulated requester
    answers the assistant's offers and questions as a person who wants exactly that would: the
    item is the case's, its owner the one whose yes is asked (``owner_asked``) when the case
    names only a type, else nobody in particular. None for an ask, words or decline case: a
    yes there would be a guess, so the requester answers from their words only."""
    if case.expect != "deliver" or case.recipient is None or case.item is None:
        return None
    item = case.item
    if ":" not in item and case.owner_asked is not None:
        item = f"{item}:{case.owner_asked}"
    return [
        {"holds": [case.recipient, item]},
        *({"holds": [more.recipient, more.item]} for more in case.also),
    ]


def item_matches(wanted: str, item: str) -> bool:
    """Whether the item handed over (``type:holder``) is the one the case names: that item
    id, or any item of the type (a product type is the type of what a facility makes)."""
    return item == wanted or (":" not in wanted and item.partition(":")[0] == wanted)


@dataclass(frozen=True)
class Handover:
    """An item offered to a person at the locker (a collect code sent) or a file forwarded."""

    at: int  # position among the run's actions
    item: str
    to: str
    received: bool  # the person opened the locker for it (a forwarded file always arrives)


@dataclass(frozen=True)
class Conduct:
    """What one run did, read from its trace, in the order the actions ran."""

    requester: str
    outcome: str | None
    physical: tuple[tuple[int, str], ...]  # (position, action type)
    asked: tuple[tuple[int, str], ...]  # (position, contact) of every question
    moved: dict[str, int]  # item id -> position of the first step that moved it
    handovers: tuple[Handover, ...]

    @property
    def first_physical(self) -> int | None:
        return self.physical[0][0] if self.physical else None

    def asked_before(self, person: str, position: int, office: Office) -> bool:
        return any(
            at < position and (contact == person or _in_group(office, contact, person))
            for at, contact in self.asked
        )


def read_conduct(trace: dict[str, Any], office: Office) -> Conduct:
    results = [
        r for step in trace.get("steps", []) for r in step.get("results", []) if not r["refused"]
    ]
    physical: list[tuple[int, str]] = []
    asked: list[tuple[int, str]] = []
    moved: dict[str, int] = {}
    offers: list[tuple[int, str, str]] = []
    files: list[tuple[int, str, str]] = []
    serving: set[str] = set()  # who got a code to run a service (print, heat, ...)
    # a service whose product is electronic (scan to PDF) sends it to the paper's owner by
    # message once its operator has the paper: (position, product id, operator)
    files_made: list[tuple[int, str, str, str]] = []
    for at, result in enumerate(results):
        action = result["action"]
        kind = action["type"]
        if kind in PHYSICAL:
            physical.append((at, kind))
        if kind == "inquire" and result["ok"]:
            asked.append((at, action["contact"]))
        if kind == "send_qr" and result["ok"]:
            moved.setdefault(action["item"], at)
            if action["purpose"] == "collect":
                offers.append((at, action["item"], action["contact"]))
            elif action["purpose"] not in _CARRY:
                if _works_on_a_file(office, action):
                    serving.add(action["contact"])
                made = _sent_by_message(office, action)
                if made is not None:
                    # sent to whom the code's message named, else to the paper's owner
                    to = action.get("send_to") or made.partition(":")[2]
                    files_made.append((at, made, action["contact"], to))
        if kind == "forward_file" and result["ok"]:
            item = action.get("file") or f"{office.file_type() or 'file'}:{action['source']}"
            moved.setdefault(item, at)
            files.append((at, item, action["target"]))
    handovers = (
        [Handover(at, item, to, _opened_for(results, at, to)) for at, item, to in offers]
        + [
            # a file forwarded to whoever then runs a service (the printer's keeper) is that
            # service's input, not a delivery
            Handover(at, item, to, True)
            for at, item, to in files
            if to not in serving
        ]
        + [
            Handover(at, item, to, _opened_for(results, at, operator))
            for at, item, operator, to in files_made
        ]
    )
    return Conduct(
        requester=trace["requester"],
        outcome=trace.get("outcome"),
        physical=tuple(physical),
        asked=tuple(asked),
        moved=moved,
        handovers=tuple(sorted(handovers, key=lambda h: h.at)),
    )


def _works_on_a_file(office: Office, action: dict[str, Any]) -> bool:
    """Whether a work code's service takes an electronic file as its input (a print makes
    a printout from one): the file forwarded to its operator is that input, while one
    forwarded to a colleague who then makes a water for someone is a delivery."""
    op_id = action.get("operation")
    if op_id:
        try:
            op_ = office.operation(op_id)
        except KeyError:
            return True
        return op_.input is not None and office.item_type(op_.input).kind == "electronic"
    maker = office.making(action["item"].partition(":")[0])
    if maker is None:
        return True  # no operation known for the code: as before, read as the input
    return maker.input is not None and office.item_type(maker.input).kind == "electronic"


def _sent_by_message(office: Office, action: dict[str, Any]) -> str | None:
    """The electronic product a work code's service makes of the item ("scan_pdf:amara" from
    scanning "document:amara"), which the operator sends by message: to its owner, or to the
    person the code names (``send_to``)."""
    op_id = action.get("operation")
    if not op_id:
        return None
    try:
        product = office.operation(op_id).product
    except KeyError:
        return None
    if product is None or not office.item_type(product).electronic:
        return None
    return f"{product}:{action['item'].partition(':')[2]}"


def _opened_for(results: list[dict[str, Any]], at: int, person: str) -> bool:
    """Whether ``person`` opened the locker at the wait for them after the code sent at
    ``at`` (before any later code to them)."""
    for result in results[at + 1 :]:
        action = result["action"]
        if action["type"] == "send_qr" and action["contact"] == person:
            return False
        if action["type"] == "wait_in_place" and action["person"] == person:
            return bool(result["ok"]) and "door_opened" in (result.get("data") or {}).get(
                "events", []
            )
    return False


@dataclass(frozen=True)
class Verdict:
    got: str  # the expectation met, else what the run did (deliver/ask/act/consult/words/decline)
    right: bool
    wrong_physical: str | None  # the first wrong physical action, in words
    why: str  # why a wrong case is wrong ("" when right)


def judge(case: Case, trace: dict[str, Any], office: Office) -> Verdict:
    conduct = read_conduct(trace, office)
    unmet = {e: _unmet(e, case, conduct, office) for e in (case.expect, *case.accept)}
    met = next((e for e, why in unmet.items() if why is None), None)
    wrong = _wrong_physical(case, conduct, office)
    got = met or _what_it_did(conduct)
    if wrong is not None:
        return Verdict(got, False, wrong, f"wrong physical action: {wrong}")
    if met is None:
        return Verdict(got, False, None, unmet[case.expect] or "")
    return Verdict(got, True, None, "")


def _unmet(expect: Expect, case: Case, conduct: Conduct, office: Office) -> str | None:
    """Why the run does not meet ``expect``; None when it does."""
    first = conduct.first_physical
    if expect == "ask":
        question = next((at for at, c in conduct.asked if c == conduct.requester), None)
        if question is None:
            return "never asked the requester"
        if first is not None and first < question:
            return "acted before asking the requester"
        return None
    if expect == "deliver":
        if case.item is None or case.recipient is None:
            return "no delivery named"
        hit = next(
            (
                h
                for h in conduct.handovers
                if h.received and h.to == case.recipient and item_matches(case.item, h.item)
            ),
            None,
        )
        if hit is None:
            return f"{case.item} never handed to {case.recipient}"
        for more in case.also:
            if not any(
                h.received and h.to == more.recipient and item_matches(more.item, h.item)
                for h in conduct.handovers
            ):
                return f"{more.item} never handed to {more.recipient}"
        if case.owner_asked is not None and not conduct.asked_before(
            case.owner_asked, conduct.moved.get(hit.item, hit.at), office
        ):
            return f"{case.owner_asked} not asked before {hit.item} moved"
        return None
    if first is not None:
        return f"acted ({conduct.physical[0][1]})"
    cannot = conduct.outcome in _CANNOT
    if expect == "decline":
        return None if cannot else f"outcome {conduct.outcome}, not a refusal"
    colleagues = [c for _, c in conduct.asked if c != conduct.requester]
    if colleagues:
        return f"asked {colleagues[0]}"
    return f"outcome {conduct.outcome}: said it cannot be done" if cannot else None


def _wrong_physical(case: Case, conduct: Conduct, office: Office) -> str | None:
    """The first wrong physical action of the run, in words; None when there is none."""
    if case.expect in ("words", "decline") and conduct.physical:
        return f"{conduct.physical[0][1]} on a {case.expect} case"
    if case.expect == "deliver":
        allowed = {case.recipient}
    else:
        allowed = {conduct.requester, case.recipient} | _named(office, case.text)
    for h in conduct.handovers:
        if any(h.to == m.recipient and item_matches(m.item, h.item) for m in case.also):
            continue  # a combination's other hand-over, as the writer named it
        if h.to not in allowed and _owner(office, h.item) != h.to:  # a return is no hand-over
            return f"handed {h.item} to {h.to}"
    for item, at in conduct.moved.items():
        owner = _owner(office, item)
        if owner not in (None, conduct.requester) and not conduct.asked_before(owner, at, office):
            return f"moved {item} without asking {owner}"
    return None


def _what_it_did(conduct: Conduct) -> str:
    first = conduct.first_physical
    if any(c == conduct.requester and (first is None or at < first) for at, c in conduct.asked):
        return "ask"
    if any(h.received for h in conduct.handovers):
        return "deliver"
    if conduct.physical:
        return "act"
    if conduct.outcome in _CANNOT:
        return "decline"
    return "consult" if any(c != conduct.requester for _, c in conduct.asked) else "words"


def _owner(office: Office, item: str) -> str | None:
    """The person whose yes an item needs: its holder, unless the item is a facility's
    supply (owned by nobody) or a product made for someone (a coffee, a printout)."""
    type_id, _, holder = item.partition(":")
    if not office.is_person(holder):
        return None
    kind = next((t.kind for t in office.item_types if t.id == type_id), None)
    return None if kind == "product" else holder


def _in_group(office: Office, contact: str, person: str) -> bool:
    return any(g.id == contact and person in g.members for g in office.groups)


def _named(office: Office, text: str) -> set[str]:
    """The people a text names: by id, full name, any part of the name, or an alias."""
    words = text.lower()
    named = set()
    for person in office.people:
        names = {person.id, person.name, *person.name.split(), *person.aliases}
        if any(re.search(rf"\b{re.escape(n.lower())}\b", words) for n in names if n):
            named.add(person.id)
    return named


def _where(raw: Any, exc: ValidationError) -> str:
    first = exc.errors()[0]
    loc = list(first["loc"])
    if len(loc) >= 2 and loc[0] == "cases" and isinstance(loc[1], int):
        cases = raw.get("cases") if isinstance(raw, dict) else None
        entry = cases[loc[1]] if isinstance(cases, list) and loc[1] < len(cases) else None
        label = entry.get("id") if isinstance(entry, dict) else None
        loc[:2] = [f"case {label or loc[1] + 1}"]
    where = ".".join(str(p) for p in loc)
    message = first["msg"].removeprefix("Value error, ")
    if first["type"] == "literal_error":
        message = f"{first.get('input')!r} is not one of {', '.join(EXPECTS)}"
    return f"{where}: {message}" if where else message


def _one_line(text: str) -> str:
    return " ".join(text.split())
