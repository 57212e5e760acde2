"""The smart lock interface: one-time QR codes and door events of the robot's locker.

The assistant issues a code bound to an instruction, a person, a purpose and an item; the
person scans it at the locker; the lock reports code_accepted / code_rejected and the door's
open/close, each attributed to the person the accepted code was issued to.
"""

from __future__ import annotations

import asyncio
import logging
from abc import ABC, abstractmethod
from collections.abc import Callable
from typing import Annotated, Literal

from pydantic import AfterValidator, BaseModel, Field

from assistantx.core import task_kinds
from assistantx.core.lifecycle import Component

logger = logging.getLogger(__name__)

# What the person does at the locker: put the item in, take it out, or take it out, work on
# it (sign, seal, copy, heat) and put it back; "produce" = make it at a facility and put it in.
# The work steps are the table of task kinds' (``task_kinds.purposes()``), checked wherever a
# code is built, so a kind added to the table brings its purpose with it.
Purpose = Annotated[str, AfterValidator(task_kinds.known_purpose)]

LockEventKind = Literal["door_opened", "door_closed", "code_accepted", "code_rejected"]
ReportedState = Literal["scanned", "used"]

# The codes whose lock reports a ``Locker`` keeps: the latest reported. A code lives minutes
# (15 by default) and one locker sees a few hand-overs an hour, so this is far more than the
# codes alive at any time (the 10,000-instruction bench, at 10,000x simulated speed with
# codes living one real minute, reports about 230 a minute); an older code has expired, its
# instruction keeps its own view of it (``IssuedCode``) and the code ledger's journal its
# state. Kept for ever, one entry per code scanned grew a long-running service for good.
CODE_REPORTS_KEPT = 1024


class QRCode(BaseModel):
    code_id: str
    payload: str = Field(description="the text encoded in the QR image; opaque to the assistant")
    lock_id: str
    instruction_id: str
    person: str
    purpose: Purpose
    item: str
    issued_at: float
    expires_at: float
    png: bytes | None = Field(default=None, exclude=True, description="rendered QR image")


class LockEvent(BaseModel):
    seq: int
    kind: LockEventKind
    time: float
    code_id: str | None = None
    person: str | None = None
    instruction_id: str | None = None
    reason: str | None = None


class LockStatus(BaseModel):
    lock_id: str
    door: Literal["open", "closed"]
    locked: bool
    active_codes: int
    contents: list[str] = Field(default_factory=list, description="item ids, where known")


class Locker(Component, ABC):
    """A locker with a magnetic lock, a QR scanner and a door sensor; started and stopped as a
    ``Component`` (connect in ``_start``, disconnect in ``_stop``)."""

    def __init__(self) -> None:
        super().__init__()
        self._subscribers: list[tuple[asyncio.Queue[LockEvent], asyncio.Event | None]] = []
        # What the lock reported of each code since we connected: "scanned" once accepted,
        # "used" once the door it opened closed (for live views; instructions keep their own).
        # The latest CODE_REPORTS_KEPT codes reported, oldest report first (``report_code``).
        self.code_states: dict[str, ReportedState] = {}
        self._listeners: list[Callable[[LockEvent], None]] = []

    @abstractmethod
    async def issue_code(
        self, *, instruction_id: str, person: str, purpose: Purpose, item: str
    ) -> QRCode:
        """Provision a one-time code at the lock and return it (with its PNG)."""

    @abstractmethod
    async def status(self) -> LockStatus:
        """Door, lock and code counts."""

    async def revoke(self, code_id: str) -> None:
        """Invalidate a code before it is used (default: codes simply expire)."""

    def subscribe(self, notify: asyncio.Event | None = None) -> asyncio.Queue[LockEvent]:
        """A queue that receives every event from now on; ``notify`` is set on each event."""
        queue: asyncio.Queue[LockEvent] = asyncio.Queue()
        self._subscribers.append((queue, notify))
        return queue

    def unsubscribe(self, queue: asyncio.Queue[LockEvent]) -> None:
        self._subscribers = [(q, n) for q, n in self._subscribers if q is not queue]

    def listen(self, listener: Callable[[LockEvent], None]) -> None:
        """Call ``listener`` with every event as it is published, before any subscriber's
        queue gets it (for whoever must record an event before anyone acts on it)."""
        self._listeners.append(listener)

    def report_code(self, code_id: str, state: ReportedState) -> None:
        """Note what the lock reported of ``code_id``; the oldest report beyond
        ``CODE_REPORTS_KEPT`` codes is forgotten."""
        self.code_states.pop(code_id, None)  # its latest report goes last
        self.code_states[code_id] = state
        while len(self.code_states) > CODE_REPORTS_KEPT:  # dicts keep insertion order
            del self.code_states[next(iter(self.code_states))]

    def _publish(self, event: LockEvent) -> None:
        if event.code_id is not None and event.kind == "code_accepted":
            self.report_code(event.code_id, "scanned")
        elif event.code_id is not None and event.kind == "door_closed":
            self.report_code(event.code_id, "used")
        for listener in list(self._listeners):
            try:
                listener(event)
            except Exception:
                # A broken recorder must not keep the event from the instructions waiting on it.
                logger.exception("lock event listener failed on event %s", event.seq)
        for queue, notify in self._subscribers:
            queue.put_nowait(event)
            if notify is not None:
                notify.set()
