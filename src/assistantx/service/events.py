"""Server-Sent Events: one instruction's trace events, or everyone's.

A stream first replays the journaled events after ``Last-Event-ID`` (or ``?after=``), then
follows live ones; the SSE ``id`` is the journal sequence number, so a reconnecting client
misses nothing and sees nothing twice. One instruction's stream always ends with its
``instruction_ended`` event: one that ended with no such event in the journal (cancelled while
it waited to start) gets one made from its record, without an ``id``.

The all-instructions stream's replay is bounded: at most ``?replay=`` events (default
``REPLAY_DEFAULT``, at most ``REPLAY_MAX``), the newest ones, after ``Last-Event-ID``,
``?after=`` or ``?since=`` (a time, epoch seconds); with none of them, just the newest
``replay`` events. When the bound cuts events off, the stream first says so with a
``replay_truncated`` event naming the ids skipped (the client can read them per instruction).
A year of events is never replayed by one request.

The framing is FastAPI's: each route is an async generator under ``EventSourceResponse``,
which writes the ``text/event-stream`` fields, the no-cache and no-proxy-buffering headers,
and a keep-alive comment whenever nothing was sent for 15 s. The checks that answer 4xx
(a bad ``Last-Event-ID``, someone else's instruction) run as dependencies, before the stream
starts, so they still get their status code instead of a 200 that ends at once.
"""

from __future__ import annotations

from collections.abc import AsyncIterator, Iterator
from dataclasses import dataclass
from typing import Annotated

from fastapi import APIRouter, Depends, Header, Query
from fastapi.sse import EventSourceResponse, ServerSentEvent

from assistantx.core.events import TraceEvent
from assistantx.service.auth import Principal
from assistantx.service.deps import Caller, Runtime, visible_instruction
from assistantx.service.errors import UnprocessableError
from assistantx.service.runtime import ServiceRuntime
from assistantx.store.journal import MAX_SEQ, EventRecord, InstructionRecord

router = APIRouter(prefix="/v1", tags=["events"])

REPLAY_DEFAULT = 1000
REPLAY_MAX = 10_000
FINAL_STATUSES = {"done", "failed", "unachievable", "cancelled"}
# The words of an end with no journaled event (the loop's own for a cancel).
_ENDED_WITHOUT_EVENT = {
    "cancelled": "The instruction was cancelled.",
    "failed": "The instruction could not be started.",
}

LastEventId = Annotated[str | None, Header(max_length=20)]
After = Annotated[int | None, Query(ge=0, le=MAX_SEQ)]


@dataclass(frozen=True)
class Replay:
    """Where a stream starts: after journal sequence ``after``, never replaying at or below
    ``floor`` (the bound of the all-instructions replay)."""

    instruction_id: str | None
    after: int
    floor: int | None = None


def _start(last_event_id: str | None, after: int | None) -> int:
    if after is not None:
        return after
    if last_event_id is None:
        return 0
    try:
        start = max(0, int(last_event_id))
    except ValueError as exc:
        raise UnprocessableError(f"Last-Event-ID {last_event_id!r} is not an event id") from exc
    if start > MAX_SEQ:
        raise UnprocessableError(f"Last-Event-ID {last_event_id!r} is beyond any event id")
    return start


def _event(record: EventRecord) -> ServerSentEvent:
    return ServerSentEvent(id=str(record.seq), event=record.event.kind, data=record.event)


def _ended_from(record: InstructionRecord) -> ServerSentEvent:
    """An ``instruction_ended`` for an instruction whose end the journal holds no event of
    (no ``id``: it has no place in the journal's sequence)."""
    summary = record.summary or _ENDED_WITHOUT_EVENT.get(record.status, "")
    event = TraceEvent(
        instruction_id=record.id,
        kind="instruction_ended",
        time=record.updated_at,
        data={
            "outcome": record.outcome
            or ("failed" if record.status == "cancelled" else record.status),
            "summary": summary,
        },
    )
    return ServerSentEvent(event="instruction_ended", data=event)


def _truncated(first: int, last: int) -> ServerSentEvent:
    payload = {"kind": "replay_truncated", "skipped_after": first, "skipped_through": last}
    return ServerSentEvent(event="replay_truncated", data=payload)


async def _stream(
    runtime: ServiceRuntime, caller: Principal, replay: Replay
) -> AsyncIterator[ServerSentEvent]:
    instruction_id, after, floor = replay.instruction_id, replay.after, replay.floor
    listener = runtime.hub.subscribe(instruction_id)
    owners: dict[str, str | None] = {}
    if floor is not None and floor > after:
        yield _truncated(after, floor)
        after = floor

    def visible(record: EventRecord) -> bool:
        if caller.is_operator:
            return True
        iid = record.event.instruction_id
        if iid not in owners:
            found = runtime.journal.instruction(iid)
            owners[iid] = found.requester if found else None
        return owners[iid] == caller.person

    last = after

    def replayed() -> Iterator[EventRecord]:
        """The journal's events after ``last`` (read in pages), advancing ``last``."""
        nonlocal last
        while True:
            page = runtime.journal.events(instruction_id, after_seq=last, limit=500)
            for record in page:
                last = record.seq
                yield record
            if len(page) < 500:
                return

    try:
        for record in replayed():
            if visible(record):
                yield _event(record)
            if instruction_id and record.event.kind == "instruction_ended":
                return
        if instruction_id:
            found = runtime.journal.instruction(instruction_id)
            if found is not None and found.status in FINAL_STATUSES:
                # Its end may have been committed between the replay and this look (the
                # journal writes on a thread of its own): read on, then end with it.
                for record in replayed():
                    if visible(record):
                        yield _event(record)
                    if record.event.kind == "instruction_ended":
                        return
                # Ended without a journaled end (cancelled before it started, or its end was
                # cut short): the stream still ends with one, from the instruction's record.
                yield _ended_from(found)
                return
        while True:  # live; FastAPI sends the keep-alive comments while this waits
            live = await listener.queue.get()
            if live is None:
                return  # dropped (slow) or shutting down: the client reconnects
            if live.seq <= last:
                continue
            last = live.seq
            if visible(live):
                yield _event(live)
            if instruction_id and live.event.kind == "instruction_ended":
                return
    finally:
        runtime.hub.unsubscribe(listener)


def _one_instruction(
    instruction_id: str,
    runtime: Runtime,
    caller: Caller,
    last_event_id: LastEventId = None,
    after: After = None,
) -> Replay:
    start = _start(last_event_id, after)  # a malformed request is 422 before any lookup
    visible_instruction(runtime, caller, instruction_id)
    return Replay(instruction_id, start)


def _all_instructions(
    runtime: Runtime,
    last_event_id: LastEventId = None,
    after: After = None,
    since: Annotated[float | None, Query(ge=0)] = None,
    replay: Annotated[int, Query(ge=0, le=REPLAY_MAX)] = REPLAY_DEFAULT,
) -> Replay:
    newest = runtime.journal.last_event_seq()
    if last_event_id is None and after is None:
        start = runtime.journal.event_seq_before(since) if since is not None else 0
        # No position given: nothing to report as skipped, the newest events simply start it.
        return Replay(None, max(start, newest - replay))
    return Replay(None, _start(last_event_id, after), floor=newest - replay)


@router.get("/instructions/{instruction_id}/events", response_class=EventSourceResponse)
async def instruction_events(
    runtime: Runtime, caller: Caller, replay: Annotated[Replay, Depends(_one_instruction)]
) -> AsyncIterator[ServerSentEvent]:
    """One instruction's events; the stream ends after its ``instruction_ended``."""
    async for event in _stream(runtime, caller, replay):
        yield event


@router.get("/events", response_class=EventSourceResponse)
async def all_events(
    runtime: Runtime, caller: Caller, replay: Annotated[Replay, Depends(_all_instructions)]
) -> AsyncIterator[ServerSentEvent]:
    """Every instruction's events (a person's token: only their own instructions); the
    replay is the newest ``replay`` events after the given id or time."""
    async for event in _stream(runtime, caller, replay):
        yield event
