"""/metrics in the Prometheus text format (token required: it reveals activity)."""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import PlainTextResponse

from assistantx.service.deps import Caller, Runtime

router = APIRouter(tags=["metrics"])


@router.get("/metrics", response_class=PlainTextResponse)
async def metrics(runtime: Runtime, caller: Caller) -> PlainTextResponse:
    return PlainTextResponse(
        runtime.metrics.render(), media_type="text/plain; version=0.0.4; charset=utf-8"
    )
