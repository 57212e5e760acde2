"""Server-Sent Events: one instruction's trace events, or everyone's.

A stream first replays the journaled events after ``Last-Event-ID`` (or ``?after=``), then
follows live ones; the SSE ``id`` is the journal sequence number, so a reconnecting client
misses nothing and sees nothing twice. One instruction's stream ends after its
``instruction_ended`` event.

The all-instructions stream's replay is bounded: at most ``?replay=`` events (default
``REPLAY_DEFAULT``, at most ``REPLAY_MAX``), the newest ones, after ``Last-Event-ID``,
``?after=`` or ``?since=`` (a time, epoch seconds); with none of them, just the newest
``replay`` events. When the bound cuts events off, the stream first says so with a
``replay_truncated`` event naming the ids skipped (the client can read them per instruction).
A year of events is never replayed by one request.
"""

from __future__ import annotations

import asyncio
import json
from collections.abc import AsyncIterator
from typing import Annotated

from fastapi import APIRouter, Header, Query
from fastapi.responses import StreamingResponse

from assistantx.memory.journal import MAX_SEQ, EventRecord
from assistantx.service.auth import Principal
from assistantx.service.deps import Caller, Runtime
from assistantx.service.errors import ForbiddenError, UnprocessableError
from assistantx.service.runtime import ServiceRuntime

router = APIRouter(prefix="/v1", tags=["events"])

KEEPALIVE_S = 15.0
REPLAY_DEFAULT = 1000
REPLAY_MAX = 10_000
FINAL_STATUSES = {"done", "failed", "unachievable", "cancelled"}


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


def _format(record: EventRecord) -> str:
    payload = record.event.model_dump(mode="json")
    return f"id: {record.seq}\nevent: {record.event.kind}\ndata: {json.dumps(payload)}\n\n"


def _truncated(first: int, last: int) -> str:
    payload = {"kind": "replay_truncated", "skipped_after": first, "skipped_through": last}
    return f"event: replay_truncated\ndata: {json.dumps(payload)}\n\n"


async def _stream(
    runtime: ServiceRuntime,
    caller: Principal,
    instruction_id: str | None,
    after: int,
    floor: int | None = None,
) -> AsyncIterator[str]:
    """``floor``: replay nothing at or below it (the bound of the all-instructions replay)."""
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

    try:
        last = after
        while True:  # replay from the journal in pages
            page = runtime.journal.events(instruction_id, after_seq=last, limit=500)
            for record in page:
                last = record.seq
                if visible(record):
                    yield _format(record)
                if instruction_id and record.event.kind == "instruction_ended":
                    return
            if len(page) < 500:
                break
        if instruction_id:
            found = runtime.journal.instruction(instruction_id)
            if found is not None and found.status in FINAL_STATUSES:
                return
        while True:
            try:
                live = await asyncio.wait_for(listener.queue.get(), KEEPALIVE_S)
            except TimeoutError:
                yield ": keepalive\n\n"
                continue
            if live is None:
                return  # dropped (slow) or shutting down: the client reconnects
            if live.seq <= last:
                continue
            last = live.seq
            if visible(live):
                yield _format(live)
            if instruction_id and live.event.kind == "instruction_ended":
                return
    finally:
        runtime.hub.unsubscribe(listener)


def _response(body: AsyncIterator[str]) -> StreamingResponse:
    return StreamingResponse(
        body,
        media_type="text/event-stream",
        headers={"Cache-Control": "no-cache", "X-Accel-Buffering": "no"},
    )


@router.get("/instructions/{instruction_id}/events")
async def instruction_events(
    instruction_id: str,
    runtime: Runtime,
    caller: Caller,
    last_event_id: Annotated[str | None, Header(max_length=20)] = None,
    after: Annotated[int | None, Query(ge=0, le=MAX_SEQ)] = None,
) -> StreamingResponse:
    start = _start(last_event_id, after)  # a malformed request is 422 before any lookup
    record = runtime.instruction(instruction_id)
    if not caller.may_act_as(record.requester):
        raise ForbiddenError("this instruction belongs to someone else")
    return _response(_stream(runtime, caller, instruction_id, start))


@router.get("/events")
async def all_events(
    runtime: Runtime,
    caller: Caller,
    last_event_id: Annotated[str | None, Header(max_length=20)] = None,
    after: Annotated[int | None, Query(ge=0, le=MAX_SEQ)] = None,
    since: Annotated[float | None, Query(ge=0)] = None,
    replay: Annotated[int, Query(ge=0, le=REPLAY_MAX)] = REPLAY_DEFAULT,
) -> StreamingResponse:
    """Every instruction's events (a person's token: only their own instructions); the
    replay is the newest ``replay`` events after the given id or time."""
    newest = runtime.journal.last_event_seq()
    if last_event_id is None and after is None:
        start = runtime.journal.event_seq_before(since) if since is not None else 0
        # No position given: nothing to report as skipped, the newest events simply start it.
        start = max(start, newest - replay)
        return _response(_stream(runtime, caller, None, start))
    start = _start(last_event_id, after)
    return _response(_stream(runtime, caller, None, start, floor=newest - replay))
