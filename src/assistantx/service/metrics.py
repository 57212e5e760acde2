"""/metrics in the Prometheus text format (operator only: it reveals everyone's activity)."""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import Response

from assistantx.service.deps import Caller, Runtime
from assistantx.service.telemetry import CONTENT_TYPE

router = APIRouter(tags=["metrics"])


@router.get("/metrics", response_class=Response)
async def metrics(runtime: Runtime, caller: Caller) -> Response:
    caller.require_operator()
    return Response(runtime.metrics.render(), media_type=CONTENT_TYPE)
