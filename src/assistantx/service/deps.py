"""Request dependencies: the runtime and the authenticated caller.

Both are ``async def`` though they never wait: FastAPI runs a plain ``def`` dependency in its
thread pool, and handing two lookups in memory to a worker thread and back, per request, cost
the event loop more than the lookups (a thread woken, the GIL taken from the loop for up to a
switch interval, a wake-up of the loop to resume) with 200 instructions running."""

from __future__ import annotations

from typing import Annotated

from fastapi import Depends, Request

from assistantx.service.auth import Principal
from assistantx.service.errors import UnavailableError
from assistantx.service.offices.directory import Offices
from assistantx.service.offices.routing import office_of
from assistantx.service.offices.submissions import OfficeDesk
from assistantx.service.runtime import ServiceRuntime
from assistantx.store.journal import InstructionRecord


async def get_runtime(request: Request) -> ServiceRuntime:
    """The runtime of the office the request addresses (``/v1/offices/{office}/...``; else
    the home office)."""
    offices: Offices | None = getattr(request.app.state, "offices", None)
    if offices is None:
        raise UnavailableError("the assistant is starting or stopping; try again shortly")
    return offices.runtime(office_of(request.scope))


Runtime = Annotated[ServiceRuntime, Depends(get_runtime)]


async def get_desk(request: Request) -> ServiceRuntime | OfficeDesk:
    """What answers instruction reads and submissions: the office's runtime, or, for an
    office another replica runs, its journal in the shared database."""
    offices: Offices | None = getattr(request.app.state, "offices", None)
    if offices is None:
        raise UnavailableError("the assistant is starting or stopping; try again shortly")
    return await offices.desk(office_of(request.scope))


Desk = Annotated[ServiceRuntime | OfficeDesk, Depends(get_desk)]


async def get_principal(request: Request) -> Principal:
    offices: Offices = request.app.state.offices
    return offices.authenticate(office_of(request.scope), request.headers.get("authorization"))


Caller = Annotated[Principal, Depends(get_principal)]


def visible_instruction(
    runtime: ServiceRuntime | OfficeDesk, caller: Principal, instruction_id: str
) -> InstructionRecord:
    """The instruction, if ``caller`` may see it (the operator sees all; a person their own).
    Someone else's id gets the very answer an unknown id gets (404), so ids cannot be probed."""
    record = runtime.instruction(instruction_id)  # NotFoundError for an unknown id
    if not caller.may_act_as(record.requester):
        raise runtime.unknown_instruction(instruction_id)
    return record
