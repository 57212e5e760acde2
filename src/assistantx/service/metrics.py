"""/metrics in the Prometheus text format (operator only: it reveals everyone's activity).

With several offices, ``/metrics`` is the home office's series (when it runs on this
replica) and the deployment's (``offices.exposition``); ``/v1/offices/{office}/metrics`` is
that office's. One office on replicas: the office's series on the replica that runs it, and
on every replica (a standby too) which replica holds it and which are up."""

from __future__ import annotations

from fastapi import APIRouter, Request
from fastapi.responses import Response

from assistantx.service.offices.directory import Offices
from assistantx.service.offices.exposition import render_offices
from assistantx.service.offices.routing import office_of
from assistantx.service.telemetry import CONTENT_TYPE

router = APIRouter(tags=["metrics"])


@router.get("/metrics", response_class=Response)
async def metrics(request: Request) -> Response:
    offices: Offices = request.app.state.offices
    office = office_of(request.scope)
    authorization = request.headers.get("authorization")
    if not offices.several and offices.leases is None:  # one office: as it always was
        runtime = offices.runtime(office)
        offices.authenticate(office, authorization).require_operator()
        return Response(runtime.metrics.render(), media_type=CONTENT_TYPE)
    # Several offices, or one on replicas (the holder's series, or a standby's none), and the
    # replicas' series: who runs the office and whether each replica is up.
    offices.authenticate(office, authorization).require_operator()
    serving = offices.serving(office)
    body = serving.metrics.render() if serving is not None else b""
    return Response(body + render_offices(offices), media_type=CONTENT_TYPE)
