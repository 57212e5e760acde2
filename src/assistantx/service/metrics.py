"""/metrics in the Prometheus text format (operator only: it reveals everyone's activity)."""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import PlainTextResponse

from assistantx.service.deps import Caller, Runtime

router = APIRouter(tags=["metrics"])


@router.get("/metrics", response_class=PlainTextResponse)
async def metrics(runtime: Runtime, caller: Caller) -> PlainTextResponse:
    caller.require_operator()
    return PlainTextResponse(
        runtime.metrics.render(), media_type="text/plain; version=0.0.4; charset=utf-8"
    )
