"""What the journal knows of how each locker code ended, so that no finished code comes back.

A one-time code ends in one of three ways: it is revoked (its hand-over timed out, or its
instruction ended first), used (the lock accepted it and the door closed after it), or it
expires. The first two are journaled here the moment they happen:

- a revocation *before* the lock is asked to withdraw the code, so a crash between the two
  leaves the journal saying "revoked" and the next start withdraws it again;
- a scan the moment the lock reports it, in one transaction with the simulated world it
  changed (``world_state``), so after a crash the world, the lock and the instruction agree
  that the hand-over happened and the resumed instruction does not ask for it again.

Expiry needs no record: a code carries its own expiry. An entry is kept for one code
lifetime after it was written, by when any code it could name has expired anyway.

It also journals which code each send minted, by the send's idempotency key, *before* the
message goes out (``CodeRecords``): a replica killed just after a code went out leaves the
key here and the message journaled as sent, and the replica that replays the step re-uses
that code instead of handing the person a second one.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Iterable
from concurrent.futures import Future
from typing import Any, Literal, cast

from assistantx.core.clock import Clock
from assistantx.core.ports.lock import LockEvent
from assistantx.runtime.executors import EarlierCode
from assistantx.store.journal import Journal

logger = logging.getLogger(__name__)

LEDGER_STATE = "lock_codes"

Ended = Literal["revoked", "scanned", "used"]
Reported = Literal["scanned", "used"]
# A later fact wins over an earlier one, never the other way round: a code revoked after the
# lock accepted it (a late revocation that found nothing to withdraw) stays "used".
_RANK: dict[str, int] = {"revoked": 0, "scanned": 1, "used": 2}

WorldState = Callable[[], dict[str, dict[str, Any]]]


class CodeLedger:
    """The journaled end of each recent code (one state row, bounded by the code lifetime)."""

    def __init__(
        self,
        journal: Journal,
        clock: Clock,
        lifetime_s: float,
        world_state: WorldState | None = None,
        *,
        transcript_after_send: bool = False,
    ) -> None:
        self._journal = journal
        self._clock = clock
        self._lifetime_s = lifetime_s
        # Set once the simulated world is restored: a lock that replays old events on connect
        # must not journal the world as it is before that.
        self.world_state = world_state
        # Whether the journal's transcript holds an outbound message only once it was sent
        # (Matrix); the built-in messenger journals it before and marks it sent after.
        self._transcript_after_send = transcript_after_send
        self._ended: dict[str, tuple[Ended, float]] = {}
        self._minted: dict[str, tuple[str, float]] = {}  # send's key -> (code id, kept until)
        body = journal.state(LEDGER_STATE) or {}
        for code_id, entry in body.get("codes", {}).items():
            state, until = entry
            if state in _RANK:
                self._ended[str(code_id)] = (cast(Ended, state), float(until))
        for key, (code_id, until) in body.get("minted", {}).items():
            self._minted[str(key)] = (str(code_id), float(until))

    def ended(self, code_id: str) -> Ended | None:
        entry = self._ended.get(code_id)
        return entry[0] if entry is not None else None

    def reported(self) -> dict[str, Reported]:
        """What the lock reported of codes before this process started (for
        ``Locker.code_states``, which otherwise knows only what it saw since)."""
        return {c: s for c, (s, _) in self._ended.items() if s != "revoked"}

    async def retire(self, code_ids: Iterable[str]) -> None:
        """Journal that these codes are revoked; call it before asking the lock to revoke."""
        if self._note(code_ids, "revoked"):
            await self._journal.aput_states({LEDGER_STATE: self._body()})

    async def minted(self, key: str, code_id: str) -> None:
        """Journal that the send under ``key`` minted ``code_id``; before it goes out."""
        self._minted[key] = (code_id, self._clock.now() + self._lifetime_s)
        await self._journal.aput_states({LEDGER_STATE: self._body()})

    def earlier(self, key: str) -> EarlierCode | None:
        """The code a send under ``key`` minted before (a replayed step), if any."""
        entry = self._minted.get(key)
        if entry is None:
            return None
        record = self._journal.outbound(key)
        delivered = record is not None and (record.status == "sent" or self._transcript_after_send)
        return EarlierCode(code_id=entry[0], delivered=delivered)

    def was_minted(self, code_id: str) -> bool:
        """Whether a send journaled minting ``code_id`` (for start-up's settling)."""
        return any(minted == code_id for minted, _ in self._minted.values())

    def on_lock_event(self, event: LockEvent) -> None:
        """A ``Locker.listen`` listener: journal a scan or a closed door before anyone acts on
        it. The write is queued before the event reaches the instructions (after this returns)
        and not waited for: whatever they do about it is journaled after it, in the journal's
        order, so a crash never keeps their records without this one. (Waiting for the commit
        here held the event loop on the writer: the longest of its stalls under load.)"""
        if event.code_id is None or event.kind not in ("code_accepted", "door_closed"):
            return
        state: Ended = "scanned" if event.kind == "code_accepted" else "used"
        if not self._note([event.code_id], state):
            return
        states = {LEDGER_STATE: self._body()}
        if self.world_state is not None:
            states.update(self.world_state())
        self._journal.queue_states(states).add_done_callback(_log_failure)

    def _note(self, code_ids: Iterable[str], state: Ended) -> bool:
        until = self._clock.now() + self._lifetime_s
        changed = False
        for code_id in code_ids:
            known = self._ended.get(code_id)
            if known is not None and _RANK[known[0]] >= _RANK[state]:
                continue
            self._ended[code_id] = (state, until)
            changed = True
        return changed

    def _body(self) -> dict[str, Any]:
        now = self._clock.now()
        self._ended = {c: e for c, e in self._ended.items() if e[1] > now}
        self._minted = {k: e for k, e in self._minted.items() if e[1] > now}
        return {
            "codes": {c: [s, until] for c, (s, until) in self._ended.items()},
            "minted": {k: [c, until] for k, (c, until) in self._minted.items()},
        }


def _log_failure(written: Future[None]) -> None:
    error = written.exception()
    if error is not None:  # the next start settles the code with the lock (code_recovery)
        logger.error("a lock event was not journaled: %s", error)
