"""/v1/instructions: submit, read, list and cancel instructions."""

from __future__ import annotations

import base64
from typing import Annotated

from fastapi import APIRouter, Query, Response

from assistantx.service.deps import Caller, Desk, Runtime, visible_instruction
from assistantx.service.errors import ForbiddenError, UnprocessableError
from assistantx.service.schemas import (
    CancelOut,
    InstructionDetail,
    InstructionIn,
    InstructionOut,
    InstructionPage,
)
from assistantx.store.journal import MAX_SEQ, Status

router = APIRouter(prefix="/v1/instructions", tags=["instructions"])


@router.post("", status_code=202, response_model=InstructionOut)
async def submit(
    body: InstructionIn, runtime: Desk, caller: Caller, response: Response
) -> InstructionOut:
    """Journal the instruction, start it, and answer 202 with its id and Location (an office
    another replica runs: journaled, and started by that replica)."""
    requester = runtime.resolver.person(body.requester)  # 422 naming an unknown person
    caller.require_person(requester)
    record = await runtime.submit(requester, body.text)
    response.headers["Location"] = f"/v1/instructions/{record.id}"
    return InstructionOut.of(record)


@router.get("", response_model=InstructionPage)
async def list_instructions(
    runtime: Desk,
    caller: Caller,
    status: Status | None = None,
    requester: Annotated[str | None, Query(max_length=100)] = None,
    limit: Annotated[int, Query(ge=1, le=200)] = 50,
    cursor: Annotated[str | None, Query(max_length=40)] = None,
) -> InstructionPage:
    """Newest first; a person sees only their own instructions."""
    if requester is not None:
        requester = runtime.resolver.person(requester)
    if not caller.is_operator:
        if requester not in (None, caller.person):
            raise ForbiddenError("you may only list your own instructions")
        requester = caller.person
    after = _decode_cursor(cursor) if cursor else 0
    records = runtime.journal.instructions(
        status=status, requester=requester, after_seq=after, limit=limit + 1
    )
    more = len(records) > limit
    records = records[:limit]
    next_cursor = _encode_cursor(records[-1].seq) if more and records else None
    return InstructionPage(items=[InstructionOut.of(r) for r in records], next_cursor=next_cursor)


@router.get("/{instruction_id}", response_model=InstructionDetail)
async def get_instruction(instruction_id: str, runtime: Desk, caller: Caller) -> InstructionDetail:
    """Status, outcome, the full trace and the dialogue."""
    return InstructionDetail.full(visible_instruction(runtime, caller, instruction_id))


@router.post("/{instruction_id}/cancel", response_model=CancelOut)
async def cancel(instruction_id: str, runtime: Runtime, caller: Caller) -> CancelOut:
    return await _cancel(instruction_id, runtime, caller)


@router.delete("/{instruction_id}", response_model=CancelOut)
async def delete(instruction_id: str, runtime: Runtime, caller: Caller) -> CancelOut:
    """Same as POST .../cancel: instructions are never erased from the journal."""
    return await _cancel(instruction_id, runtime, caller)


async def _cancel(instruction_id: str, runtime: Runtime, caller: Caller) -> CancelOut:
    record = visible_instruction(runtime, caller, instruction_id)
    cancelled = await runtime.cancel(instruction_id)
    return CancelOut(
        id=instruction_id,
        cancelled=cancelled,
        status="cancelled" if cancelled else record.status,
    )


def _encode_cursor(seq: int) -> str:
    return base64.urlsafe_b64encode(f"s{seq}".encode()).decode().rstrip("=")


def _decode_cursor(cursor: str) -> int:
    problem = UnprocessableError(f"cursor {cursor!r} is not a cursor this API gave out")
    try:
        raw = base64.urlsafe_b64decode(cursor + "=" * (-len(cursor) % 4)).decode()
    except (ValueError, UnicodeDecodeError) as exc:
        raise problem from exc
    if not raw.startswith("s") or not raw[1:].isascii() or not raw[1:].isdigit():
        raise problem
    seq = int(raw[1:])
    if seq > MAX_SEQ:
        raise problem
    return seq
