"""/healthz (the process answers) and /readyz (the assistant runs); no token needed."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import JSONResponse

router = APIRouter(tags=["health"])


@router.get("/healthz")
async def healthz() -> dict[str, str]:
    return {"status": "ok"}


@router.get("/readyz", response_model=None)
async def readyz(request: Request) -> JSONResponse | dict[str, Any]:
    runtime = getattr(request.app.state, "runtime", None)
    if runtime is None or not runtime.ready:
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
