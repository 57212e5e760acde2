"""The locker's logic with no I/O: codes, scans, a magnetic lock, a door sensor, events.

One ``LockController`` per physical locker. It holds the codes the assistant provisioned,
validates scans (each code opens the door once), drives the simulated lock and door, and
keeps a bounded log of ``LockEvent`` with increasing sequence numbers, so a client that
reconnects asks for everything after the last sequence it saw. ``epoch`` changes when the
controller restarts, telling such a client that sequence numbers started over.

Scan checks, in order (the first failing one is the rejection reason): ``malformed``,
``unknown_key``, ``forged`` (from decoding), ``other_lock``, ``expired``, ``not_yet_valid``,
``replayed``, ``revoked``, ``not_provisioned``, ``door_open``. A rejected scan consumes
nothing: a valid code scanned while the door is open still works once the door is closed.
"""

from __future__ import annotations

import logging
import secrets
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal

from assistantx.adapters.lock.protocol.codes import CodeClaims, unseal
from assistantx.adapters.lock.protocol.keys import Keyring
from assistantx.core.clock import Clock
from assistantx.core.errors import InvalidCodeError, LockCommandError
from assistantx.core.ports.lock import LockEvent, LockEventKind, LockStatus

logger = logging.getLogger(__name__)

RejectReason = Literal[
    "malformed",
    "unknown_key",
    "forged",
    "other_lock",
    "expired",
    "not_yet_valid",
    "replayed",
    "revoked",
    "not_provisioned",
    "door_open",
]
# Who opened the door without a code.
MAINTENANCE = "maintenance"
# Tolerated difference between the assistant's clock and the lock's, in seconds.
DEFAULT_CLOCK_SKEW_S = 30.0

EventListener = Callable[[LockEvent], None]


@dataclass(frozen=True)
class ScanResult:
    """The outcome of one scan: the accepted/rejected event, then any door event."""

    events: tuple[LockEvent, ...]

    @property
    def decision(self) -> LockEvent:
        return self.events[0]

    @property
    def accepted(self) -> bool:
        return self.decision.kind == "code_accepted"


@dataclass(frozen=True)
class EventBacklog:
    """Events after a client's last sequence; ``complete`` is False when the bounded log
    had already dropped some of them (or the client's epoch is stale)."""

    epoch: str
    events: tuple[LockEvent, ...]
    complete: bool


@dataclass
class _Opening:
    person: str | None
    instruction_id: str | None
    code_id: str | None
    claims: CodeClaims | None


class LockController:
    def __init__(
        self,
        lock_id: str,
        keyring: Keyring,
        clock: Clock,
        *,
        event_log_size: int = 1024,
        clock_skew_s: float = DEFAULT_CLOCK_SKEW_S,
        contents: list[str] | None = None,
    ) -> None:
        if event_log_size < 1:
            raise ValueError("event_log_size must be >= 1")
        self.lock_id = lock_id
        self.keyring = keyring
        self.clock = clock
        self.clock_skew_s = clock_skew_s
        self.epoch = secrets.token_hex(8)
        self._provisioned: dict[str, CodeClaims] = {}
        # code id -> expiry; remembered until the code would have expired anyway.
        self._used: dict[str, float] = {}
        self._revoked: dict[str, float] = {}
        self._log: deque[LockEvent] = deque(maxlen=event_log_size)
        self._seq = 0
        self._listeners: list[EventListener] = []
        self._opening: _Opening | None = None
        self._contents: list[str] = list(contents or [])

    # -- state ------------------------------------------------------------------------

    @property
    def door_open(self) -> bool:
        return self._opening is not None

    @property
    def last_seq(self) -> int:
        return self._seq

    def status(self) -> LockStatus:
        self._forget_expired()
        return LockStatus(
            lock_id=self.lock_id,
            door="open" if self.door_open else "closed",
            locked=not self.door_open,
            active_codes=len(self._provisioned),
            contents=list(self._contents),
        )

    def add_listener(self, listener: EventListener) -> None:
        self._listeners.append(listener)

    def remove_listener(self, listener: EventListener) -> None:
        if listener in self._listeners:
            self._listeners.remove(listener)

    def events_since(self, seq: int, epoch: str | None = None) -> EventBacklog:
        """Logged events with a sequence number above ``seq``."""
        if epoch is not None and epoch != self.epoch:
            seq = 0  # sequence numbers started over; send everything we still have
        events = tuple(e for e in self._log if e.seq > seq)
        oldest_kept = self._log[0].seq if self._log else self._seq + 1
        complete = (epoch is None or epoch == self.epoch) and seq >= oldest_kept - 1
        return EventBacklog(epoch=self.epoch, events=events, complete=complete)

    # -- commands from the assistant ----------------------------------------------------

    def provision(self, payload: str) -> CodeClaims:
        """Accept a sealed code for later scanning; re-provisioning the same code is a no-op."""
        self._forget_expired()
        claims = unseal(payload, self.keyring)
        if claims.lock_id != self.lock_id:
            raise InvalidCodeError("other_lock", f"code is for lock {claims.lock_id!r}")
        if claims.expires_at <= self.clock.now():
            raise InvalidCodeError("expired", "code expired before it was provisioned")
        if claims.code_id in self._used or claims.code_id in self._revoked:
            raise LockCommandError("code_spent", f"code {claims.code_id} was used or revoked")
        self._provisioned[claims.code_id] = claims
        logger.info(
            "lock %s: provisioned code %s for %s", self.lock_id, claims.code_id, claims.person
        )
        return claims

    def revoke(self, code_id: str) -> None:
        self._forget_expired()
        claims = self._provisioned.pop(code_id, None)
        if claims is None:
            raise LockCommandError("unknown_code", f"no active code {code_id!r} to revoke")
        self._revoked[code_id] = claims.expires_at
        logger.info("lock %s: revoked code %s", self.lock_id, code_id)

    def retire(self, code_id: str, until: float) -> None:
        """Refuse ``code_id`` as revoked until ``until`` (its expiry), whether or not it is
        provisioned here: a lock that restarted learns what was withdrawn before."""
        self._provisioned.pop(code_id, None)
        if code_id not in self._used:
            self._revoked[code_id] = max(until, self._revoked.get(code_id, until))

    def open_for_maintenance(self, reason: str = "") -> LockEvent:
        if self.door_open:
            raise LockCommandError("door_open", "the door is already open")
        self._opening = _Opening(person=MAINTENANCE, instruction_id=None, code_id=None, claims=None)
        return self._emit("door_opened", person=MAINTENANCE, reason=reason or None)

    # -- the physical world -------------------------------------------------------------

    def scan(self, payload: str) -> ScanResult:
        """A code held up to the scanner."""
        self._forget_expired()
        try:
            claims = unseal(payload, self.keyring)
        except InvalidCodeError as exc:
            return self._reject(exc.reason, None)
        reason = self._rejection(claims)
        if reason is not None:
            return self._reject(reason, claims)
        del self._provisioned[claims.code_id]
        self._used[claims.code_id] = claims.expires_at
        accepted = self._emit_for("code_accepted", claims)
        self._opening = _Opening(claims.person, claims.instruction_id, claims.code_id, claims)
        opened = self._emit_for("door_opened", claims)
        return ScanResult((accepted, opened))

    def close(self) -> LockEvent:
        """The person shuts the door; the magnetic lock engages."""
        opening = self._opening
        if opening is None:
            raise LockCommandError("door_closed", "the door is already closed")
        self._opening = None
        if opening.claims is not None:
            self._update_contents(opening.claims)
        return self._emit(
            "door_closed",
            code_id=opening.code_id,
            person=opening.person,
            instruction_id=opening.instruction_id,
        )

    # -- internals ----------------------------------------------------------------------

    def _rejection(self, claims: CodeClaims) -> RejectReason | None:
        now = self.clock.now()
        if claims.lock_id != self.lock_id:
            return "other_lock"
        if now >= claims.expires_at:
            return "expired"
        if claims.issued_at > now + self.clock_skew_s:
            return "not_yet_valid"
        if claims.code_id in self._used:
            return "replayed"
        if claims.code_id in self._revoked:
            return "revoked"
        if claims.code_id not in self._provisioned:
            return "not_provisioned"
        if self.door_open:
            return "door_open"
        return None

    def _reject(self, reason: str, claims: CodeClaims | None) -> ScanResult:
        logger.info("lock %s: rejected a scan (%s)", self.lock_id, reason)
        if claims is None or reason == "other_lock":
            # Claims under another lock's name are not ours to attribute.
            return ScanResult((self._emit("code_rejected", reason=reason),))
        return ScanResult((self._emit_for("code_rejected", claims, reason=reason),))

    def _update_contents(self, claims: CodeClaims) -> None:
        # The lock's belief from purposes; the simulator holds the truth.
        if claims.purpose in ("deposit", "produce") and claims.item not in self._contents:
            self._contents.append(claims.item)
        elif claims.purpose == "collect" and claims.item in self._contents:
            self._contents.remove(claims.item)

    def _forget_expired(self) -> None:
        now = self.clock.now()
        for table in (self._used, self._revoked):
            for code_id in [c for c, expiry in table.items() if expiry <= now]:
                del table[code_id]
        for code_id in [c for c, claims in self._provisioned.items() if claims.expires_at <= now]:
            # A late scan still reads "expired": that check runs on the sealed claims.
            del self._provisioned[code_id]

    def _emit_for(
        self, kind: LockEventKind, claims: CodeClaims, reason: str | None = None
    ) -> LockEvent:
        return self._emit(
            kind,
            code_id=claims.code_id,
            person=claims.person,
            instruction_id=claims.instruction_id,
            reason=reason,
        )

    def _emit(
        self,
        kind: LockEventKind,
        *,
        code_id: str | None = None,
        person: str | None = None,
        instruction_id: str | None = None,
        reason: str | None = None,
    ) -> LockEvent:
        self._seq += 1
        event = LockEvent(
            seq=self._seq,
            kind=kind,
            time=self.clock.now(),
            code_id=code_id,
            person=person,
            instruction_id=instruction_id,
            reason=reason,
        )
        self._log.append(event)
        for listener in list(self._listeners):
            try:
                listener(event)
            except Exception:
                # One broken subscriber must not stop the lock or starve the others.
                logger.exception("lock %s: event listener failed", self.lock_id)
        return event
