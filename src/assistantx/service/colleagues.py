"""The simulated colleagues behind the built-in messenger, and the simulated world's snapshot.

With ``ASSISTANTX_PEOPLE=simulated`` the SimOffice's rule-based people read what the assistant
sends through the built-in messenger and answer through it, so their replies land in the same
journaled transcripts a human's would. Their world (who holds what, the codes in their hands,
where the robot stands) is the demo's physical world; it is snapshotted into the journal with
every checkpoint, and restored on start-up, so a restart does not undo a hand-over.

A code's payload is a credential (it opens the locker), so it never enters the journal: the
snapshot names each held code by a digest of its payload, and the payloads themselves live
in the people's "phones", an owner-only file beside the journal (``CodePhones``), written
before the snapshot that refers to them.
"""

from __future__ import annotations

import asyncio
import dataclasses
import functools
import hashlib
import json
import logging
import operator
import os
from pathlib import Path
from typing import Any

from assistantx.adapters.messenger.builtin import BuiltinMessenger
from assistantx.core.lifecycle import cancel_and_wait
from assistantx.core.ports.messenger import InboundMessage, OutboundMessage
from assistantx.service.live_memo import LiveMemo
from assistantx.sim.office import HeldCode, SimOffice
from assistantx.store.journal import Journal

logger = logging.getLogger(__name__)

SIM_STATE = "sim_world"
RELAY_DRAIN_S = 5.0  # at stop, the most the queued colleagues' messages are waited for


class InboxRelay(asyncio.Queue[InboundMessage]):
    """Stands in for the simulator's inbox: what a simulated person writes goes to the
    built-in messenger (journal + assistant), not to a private queue.

    The simulator puts without awaiting; one task hands the messages on in order, awaiting
    the journal's writer, so the event loop never blocks on a commit (a blocking accept per
    message was a sixth of the loop's time with 200 instructions running). Used as an async
    context: the task starts on entry; on exit what is queued is handed on, then it stops."""

    def __init__(self, messenger: BuiltinMessenger) -> None:
        super().__init__()
        self._messenger = messenger
        self._task: asyncio.Task[None] | None = None

    async def __aenter__(self) -> InboxRelay:
        if self._task is None:
            self._task = asyncio.create_task(self._hand_on(), name="colleagues-inbox")
        return self

    async def __aexit__(self, *exc_info: object) -> None:
        if self._task is None:
            return
        try:
            await asyncio.wait_for(self.join(), RELAY_DRAIN_S)
        except TimeoutError:
            logger.warning("%d simulated colleagues' messages not journaled at stop", self.qsize())
        await cancel_and_wait(self._task)
        self._task = None

    async def _hand_on(self) -> None:
        while True:
            # Everything queued meanwhile goes in one journal commit: one commit per message
            # fell behind 200 running instructions (thousands queued at the bench's end).
            batch = [await self.get()]
            while not self.empty():
                batch.append(self.get_nowait())
            try:
                await self._messenger.aaccept_many(batch)
            except Exception:  # one bad batch must not stop the colleagues' inbox
                logger.exception("%d simulated colleagues' messages not journaled", len(batch))
            finally:
                for _ in batch:
                    self.task_done()


def connect_colleagues(sim: SimOffice, messenger: BuiltinMessenger) -> InboxRelay:
    """Connects the simulated people to the built-in messenger; the caller enters the
    returned relay (``async with``) for as long as they talk."""

    async def relay(message: OutboundMessage) -> None:
        await sim.messenger.send(message)

    messenger.relay_to(relay)
    inbox = InboxRelay(messenger)
    sim.messenger.connect_inbox(inbox)
    return inbox


def snapshot(sim: SimOffice) -> dict[str, Any]:
    world = sim.world
    return {
        "holder": dict(world.holder),
        "signed": sorted(world.signed),
        "sealed": sorted(world.sealed),
        "printed": sorted(world.printed),
        "copied": sorted(world.copied),
        "heated": sorted(world.heated),
        "made": sorted(world.made),
        "received": sorted(world.received),
        "messages_to": dict(world.messages_to),
        "codes": [dict(r) for r in _HELD_CODE_RECORDS.values(map(_field_values, sim.codes))],
        "told": list(_sorted_told(frozenset(sim.told))),
        "robot": {"place": sim.robot.place, "odometer_m": sim.robot.odometer_m},
    }


@functools.lru_cache(maxsize=256)
def code_ref(payload: str) -> str:
    """Names a payload in the journal without revealing it (remembered: the snapshot names
    every held code at every checkpoint). People hold a few codes at a time; 4,096 payloads
    (one or two per fetch) filled only after thousands of instructions, growing till then."""
    return hashlib.sha256(payload.encode("utf-8")).hexdigest()[:32]


_ALL_FIELDS = tuple(f.name for f in dataclasses.fields(HeldCode))
_field_values = operator.attrgetter(*_ALL_FIELDS)

# The snapshot is built at every checkpoint (a few hundred a second with 200 instructions
# running), and most of its parts are as they were: each held code's record and the sorted
# list of who was told are remembered by their contents (all plain values), so an unchanged
# part costs a lookup, not a rebuild (sorting a few hundred pairs was a third of a snapshot).
# A code's record is remembered while the code is held (``LiveMemo``): an LRU cache of 4,096
# kept ended codes' records too and grew for most of a 10,000-instruction run.


def _held_code_record(values: tuple[Any, ...]) -> dict[str, Any]:
    """A held code (its field values) as the snapshot names it: the payload by its digest.
    Shared by every snapshot naming it: copied before use."""
    record = dict(zip(_ALL_FIELDS, values, strict=True))
    record["ref"] = code_ref(record.pop("payload"))
    return record


@functools.lru_cache(maxsize=1)
def _sorted_told(told: frozenset[tuple[str | None, str]]) -> tuple[tuple[str, str], ...]:
    return tuple(sorted((i or "", p) for i, p in told))


def phone_entries(codes: list[HeldCode]) -> dict[str, str]:
    """What the phones keep of ``codes``, by ``code_ref``: each whole held code with its
    payload, so a code that reached a phone after the last journaled snapshot (the process
    died in between) is still in that person's hands after a restart, as with a real phone."""
    held = [c for c in codes if c.payload]
    entries = _PHONE_ENTRIES.values(map(_field_values, held))
    return {code_ref(c.payload): e for c, e in zip(held, entries, strict=True)}


def _phone_entry(values: tuple[Any, ...]) -> str:
    # Remembered by the code's field values (all plain): the phones are compared at every
    # checkpoint, and encoding each held code again (``dataclasses.asdict`` deep-copies) took
    # 2 ms of the loop per checkpoint with 100 codes held.
    return json.dumps(dict(zip(_ALL_FIELDS, values, strict=True)), sort_keys=True)


_HELD_CODE_RECORDS = LiveMemo(_held_code_record)
_PHONE_ENTRIES = LiveMemo(_phone_entry)


def _phone_code(entry: str) -> HeldCode | None:
    """The held code a phone entry keeps; None for an entry of the older payload-only kind."""
    if not entry.startswith("{"):
        return None
    return HeldCode(**{**json.loads(entry), "scheduled": False})


def _phone_payload(entry: str) -> str:
    code = _phone_code(entry)
    return code.payload if code is not None else entry


class CodePhones:
    """The QR payloads simulated people hold, kept out of the journal in an owner-only file."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._written: dict[str, str] | None = None

    def save(self, codes: list[HeldCode]) -> None:
        held = phone_entries(codes)
        if held == self._written:
            return
        temporary = self.path.with_name(f".{self.path.name}.tmp")
        fd = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            json.dump(held, handle)
        temporary.replace(self.path)
        self._written = held

    def load(self) -> dict[str, str]:
        try:
            data = json.loads(self.path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            return {}
        except (OSError, ValueError) as exc:
            logger.warning("simulated people's codes unreadable (%s); they hold none", exc)
            return {}
        return {str(k): str(v) for k, v in data.items()} if isinstance(data, dict) else {}


def _held_code(record: dict[str, Any], phones: dict[str, str]) -> HeldCode | None:
    fields = {k: v for k, v in record.items() if k != "ref"}
    entry = phones.get(str(record.get("ref")))
    payload = fields.pop("payload", None) or (_phone_payload(entry) if entry else None)
    if not payload:
        return None  # the phone lost it: the person holds no code
    return HeldCode(**{**fields, "payload": payload, "scheduled": False})


def _held_codes(state: dict[str, Any], phones: dict[str, str]) -> list[HeldCode]:
    """The codes in people's hands: those the journaled world names, and those that reached a
    phone after it was journaled (the message went out, the process died before the next
    snapshot)."""
    named = {str(c.get("ref")) for c in state["codes"]}
    held = [_held_code(c, phones) for c in state["codes"]]
    later = [_phone_code(entry) for ref, entry in phones.items() if ref not in named]
    return [c for c in [*held, *later] if c is not None]


def held_payloads(state: dict[str, Any], phones: dict[str, str]) -> list[str]:
    """The payloads of the codes in people's hands (``phones``: from ``CodePhones.load``),
    for the start-up to settle before ``restore``."""
    return [c.payload for c in _held_codes(state, phones)]


def restore(
    sim: SimOffice,
    state: dict[str, Any],
    payloads: dict[str, str] | None = None,
    live: set[str] | None = None,
) -> None:
    """Put the simulated world back as it was journaled. People keep only the codes in
    ``live``: those the start-up found still open for a hand-over to come (the lock was armed
    with them); a code that was revoked, used or expired is gone from their hands, so nobody
    comes to the robot with it."""
    world = sim.world
    world.holder = {str(k): str(v) for k, v in state["holder"].items()}
    world.signed = {(a, b) for a, b in state["signed"]}
    world.sealed = {(a, b) for a, b in state["sealed"]}
    world.printed = set(state["printed"])
    world.copied = set(state["copied"])
    world.heated = set(state["heated"])
    world.made = set(state["made"])
    world.received = {(a, b) for a, b in state["received"]}
    world.messages_to = {str(k): int(v) for k, v in state["messages_to"].items()}
    sim.told = {(i or None, p) for i, p in state["told"]}
    held = _held_codes(state, payloads or {})
    sim.codes = [c for c in held if not c.done and c.payload in (live or set())]
    # A code that reached a phone after the snapshot came in a message: its holder was told.
    sim.told |= {(c.instruction_id, c.person) for c in sim.codes}
    robot = state["robot"]
    sim.robot.restore(robot["place"] or sim.office.robot.home, float(robot["odometer_m"]))
    sim.on_robot_arrived()  # people with a code for this place come (again)


def reask_unanswered(sim: SimOffice, journal: Journal, instruction_id: str) -> int:
    """Questions sent before a restart whose answer never arrived: the simulated person reads
    them again (their pending reply was lost with the process). Returns how many."""
    records = journal.messages_of(instruction_id)
    answered = {r.in_reply_to for r in records if r.direction == "in" and r.in_reply_to}
    count = 0
    for r in records:
        if r.direction == "out" and r.status == "sent" and r.question_id not in answered:
            if r.question_id is None:
                continue
            sim.on_message(OutboundMessage.model_validate(r.body))
            count += 1
    return count
