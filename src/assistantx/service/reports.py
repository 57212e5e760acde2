"""/v1/reports/usage and /v1/surveys: the usage report and the surveys behind it.

The feedback part they read (the survey store and the Surveyor) is built by the runtime's
start, like every other component (``service/feedback_wiring.py``).

Endpoints (a person sees their own figures; the operator everyone's, or one person's with
``?person=``):

- ``GET /v1/reports/usage?from=&to=`` — the report as JSON
- ``GET /v1/reports/usage.md?from=&to=`` — the Markdown summary
- ``GET /v1/reports/usage/charts/{outcomes|survey|walking}.png?from=&to=`` — a PNG chart
- ``GET /v1/surveys/{instruction_id}`` — one survey: state, answers, comment, replies

``from``/``to``: YYYY-MM-DD (``to`` includes that day), an ISO date-time (UTC unless a zone
is given) or epoch seconds; ``from`` inclusive, ``to`` exclusive.
"""

from __future__ import annotations

import asyncio
import logging
from dataclasses import dataclass
from typing import Annotated, Any

from fastapi import APIRouter, Depends, Query, Request
from fastapi.responses import PlainTextResponse, Response
from pydantic import BaseModel

from assistantx.feedback.report import (
    CHARTS,
    ChartName,
    UsageReport,
    load_report,
    parse_time,
    render_chart,
    render_markdown,
)
from assistantx.feedback.survey import Survey
from assistantx.service.auth import Principal
from assistantx.service.deps import Caller, Runtime
from assistantx.service.errors import NotFoundError, UnprocessableError
from assistantx.service.runtime import ServiceRuntime

logger = logging.getLogger(__name__)

router = APIRouter(tags=["reports"])


def _period(
    runtime: ServiceRuntime,
    caller: Principal,
    start: str | None,
    end: str | None,
    person: str | None,
) -> tuple[float | None, float | None, str | None]:
    try:
        lo = parse_time(start) if start else None
        hi = parse_time(end, end=True) if end else None
    except ValueError as exc:
        raise UnprocessableError(str(exc)) from exc
    if lo is not None and hi is not None and hi <= lo:
        raise UnprocessableError("'to' must come after 'from'")
    requester: str | None = runtime.resolver.person(person) if person else None  # 422 naming it
    if not caller.is_operator:
        if requester is not None:
            caller.require_person(requester)
        requester = caller.person
    return lo, hi, requester


_From = Annotated[str | None, Query(alias="from", max_length=40, description="start (incl.)")]
_To = Annotated[str | None, Query(alias="to", max_length=40, description="end (excl.)")]
_Person = Annotated[str | None, Query(max_length=100, description="operator: one person")]


@dataclass(frozen=True)
class _Asked:
    """What a usage report's request asks for: its office, its caller, the period and person
    of its query (``?from=&to=&person=``), the same for every form of the report."""

    runtime: ServiceRuntime
    caller: Principal
    start: str | None
    end: str | None
    person: str | None


async def _asked(  # async: FastAPI would run a plain function in its thread pool
    runtime: Runtime,
    caller: Caller,
    start: _From = None,
    end: _To = None,
    person: _Person = None,
) -> _Asked:
    return _Asked(runtime, caller, start, end, person)


Asked = Annotated[_Asked, Depends(_asked)]


async def _report(asked: _Asked) -> UsageReport:
    runtime = asked.runtime
    lo, hi, requester = _period(runtime, asked.caller, asked.start, asked.end, asked.person)
    store = runtime.feedback.store
    names = {p.id: p.name for p in runtime.office.people}
    return await asyncio.to_thread(
        load_report, store, lo, hi, runtime.clock.now(), requester=requester, names=names
    )


@router.get("/v1/reports/usage", response_model=UsageReport)
async def usage(asked: Asked) -> UsageReport:
    """Instructions by kind and outcome, times, group requests, survey shares, walking."""
    return await _report(asked)


@router.get("/v1/reports/usage.md", response_class=PlainTextResponse)
async def usage_markdown(asked: Asked) -> PlainTextResponse:
    report = await _report(asked)
    return PlainTextResponse(render_markdown(report), media_type="text/markdown; charset=utf-8")


@router.get(
    "/v1/reports/usage/charts/{name}.png",
    response_class=Response,
    responses={200: {"content": {"image/png": {}}}},
)
async def usage_chart(name: str, asked: Asked) -> Response:
    if name not in CHARTS:
        raise NotFoundError(f"no chart {name!r}; charts: {', '.join(CHARTS)}")
    chart: ChartName = name
    report = await _report(asked)
    png = await asyncio.to_thread(render_chart, report, chart)
    return Response(png, media_type="image/png", headers={"Cache-Control": "no-store"})


class SurveyOut(BaseModel):
    survey: Survey
    replies: list[dict[str, Any]]


@router.get("/v1/surveys/{instruction_id}", response_model=SurveyOut)
async def survey(
    request: Request, instruction_id: str, runtime: Runtime, caller: Caller
) -> SurveyOut:
    store = runtime.feedback.store
    found = store.survey(instruction_id)
    if found is None or not caller.may_act_as(found.person):
        # Someone else's survey is answered like a missing one: ids cannot be probed.
        raise NotFoundError(f"no survey for instruction {instruction_id!r}")
    replies = [
        {"time": t, "text": text, "effect": effect}
        for t, text, effect in store.replies(instruction_id)
    ]
    return SurveyOut(survey=found, replies=replies)
