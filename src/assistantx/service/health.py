"""/healthz (the process answers) and /readyz (the assistant runs); no token needed.

A standby replica of one office answers /readyz 503 ``standby``, naming itself and the
replica that holds the office (a load balancer sends traffic to the holder, and an operator
reads who it is)."""

from __future__ import annotations

import asyncio
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import JSONResponse

from assistantx.service.offices.directory import Offices
from assistantx.service.offices.routing import office_of

router = APIRouter(tags=["health"])


@router.get("/healthz")
async def healthz() -> dict[str, str]:
    return {"status": "ok"}


@router.get("/readyz", response_model=None)
async def readyz(request: Request) -> JSONResponse | dict[str, Any]:
    offices: Offices | None = getattr(request.app.state, "offices", None)
    office = office_of(request.scope)
    if offices is not None and offices.several and office is None:
        return _deployment_ready(offices)
    runtime = offices.serving(office) if offices is not None else None
    if runtime is None:
        if offices is not None and offices.started and offices.leases is not None:
            # One office on replicas, this one a standby: it answers, the office is elsewhere.
            holder = await asyncio.to_thread(offices.holder, offices.home)
            standby = {"status": "standby", "replica": offices.replica, "holder": holder}
            return JSONResponse(standby, status_code=503)
        return JSONResponse({"status": "starting"}, status_code=503)
    ready: dict[str, Any] = {
        "status": "ready",
        "running": len(runtime.assistant.running),
        "resumed": runtime.resumed,
        # Simulated durations pass this many times faster than real time (the page says so).
        "speedup": runtime.clock.speedup,
    }
    office_lease = runtime.office_lease
    if office_lease is not None and office_lease.lease is not None:  # replicas on PostgreSQL
        lease = office_lease.lease
        ready["replica"] = {
            "id": lease.holder,
            "office": lease.office,
            "fencing_token": lease.token,
            "lease_expires_at": lease.expires_at,
        }
    return ready


def _deployment_ready(offices: Offices) -> JSONResponse | dict[str, Any]:
    """Several offices: this replica answers once it started (on PostgreSQL: once it took
    its first share of the offices); each office's state is in ``offices``."""
    if not offices.started:
        return JSONResponse({"status": "starting"}, status_code=503)
    return {
        "status": "ready",
        "replica": offices.replica,
        "offices": {office: offices.status(office) for office in offices.slots},
    }
