"""The ASGI app: ``create_app(settings)``; the lifespan builds the runtime (adapters entered
through an AsyncExitStack) and tears it down in reverse order. Nothing runs at import time."""

from __future__ import annotations

import asyncio
import logging
import time
from collections.abc import AsyncIterator, Callable
from contextlib import AsyncExitStack, asynccontextmanager
from pathlib import Path

from fastapi import FastAPI
from fastapi.responses import FileResponse
from fastapi.staticfiles import StaticFiles
from starlette.routing import BaseRoute, Route

from assistantx.adapters.messenger.matrix.appservice import (
    MAX_PUSH_BODY_BYTES,
    PUSH_PATH_PREFIX,
    push_too_large_error,
)
from assistantx.core.settings import Settings
from assistantx.service import (
    dashboard,
    devices,
    events,
    health,
    instructions,
    memory,
    messages,
    metrics,
    reports,
    whoami,
)
from assistantx.service.body_limit import BodyLimit, PathLimit
from assistantx.service.client_gone import ClientGone
from assistantx.service.datalock import DataDirLock
from assistantx.service.errors import install_error_handlers
from assistantx.service.offices import routes as office_routes
from assistantx.service.offices.directory import Offices
from assistantx.service.offices.routing import OfficeRouting
from assistantx.service.pushes import OfficePushes
from assistantx.service.request_metrics import RequestMetrics
from assistantx.service.route_tables import build_route_tables, import_thread_backend
from assistantx.service.runtime import ServiceRuntime
from assistantx.service.security_headers import SecurityHeaders
from assistantx.service.telemetry import ServiceMetrics
from assistantx.service.turns import RequestsFirst

logger = logging.getLogger(__name__)

STATIC_DIR = Path(__file__).resolve().parents[1] / "static"


PUSH_ROUTE = PUSH_PATH_PREFIX + "{rest:path}"
"""Every office's push endpoints, told apart by their homeserver token (``pushes``)."""

PATH_BODY_LIMITS = (PathLimit(PUSH_PATH_PREFIX, MAX_PUSH_BODY_BYTES, push_too_large_error),)
"""Routes with their protocol's own body limit and 413 format: a Matrix transaction may hold
100 events of 64 KiB, and a 413 the homeserver cannot read would make it retry for ever."""


def create_app(
    settings: Settings | None = None,
    *,
    on_ready: Callable[[Offices], None] | None = None,
    data_lock: DataDirLock | None = None,
    on_lease_lost: Callable[[], None] | None = None,
) -> FastAPI:
    """The app; ``on_ready`` is called once the assistant runs (the CLI prints where to go);
    ``data_lock``: the data folder's lock, when the caller holds it already;
    ``on_lease_lost``: one office, replicas: another replica took the office over."""
    settings = settings or Settings()
    offices = Offices(settings, data_lock, on_lease_lost)  # DeploymentError: a bad file
    pushes = OfficePushes()
    mounted: list[BaseRoute] = []

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        async with AsyncExitStack() as stack:
            # Unmounted once everything stopped: a push during shutdown still gets the
            # stopped office's 503 and is retried by the homeserver.
            stack.callback(_unmount, app, mounted)

            def mount_pushes(office_id: str, runtime: ServiceRuntime) -> None:
                # Each office as it starts here, whenever that is: its homeserver's pushes.
                if pushes.add(office_id, runtime) and not mounted:
                    mounted.append(_mount_first(app, Route(PUSH_ROUTE, endpoint=pushes)))

            offices.on_started = mount_pushes
            await offices.start(stack)
            # Off the loop, before ready: FastAPI would build them at the first requests.
            await asyncio.to_thread(build_route_tables, app)
            await asyncio.to_thread(import_thread_backend)
            running = offices.serving(None)
            # The process's CPU time so far (all threads): what a start cost, as the service
            # itself counts it (bench/serve_start.py reads it; from outside, a probe's answer
            # comes later and also counts what runs after ready, the reasoner's warm-up).
            spent = time.process_time()
            if offices.several:
                logger.info("offices ready on replica %s after %.2f CPU-s", offices.replica, spent)
            elif running is None:  # one office on replicas: another replica holds it
                logger.info("replica %s answers as a standby", offices.replica)
            else:
                name = running.assistant.parts.reasoner_name
                logger.info("assistant ready (%s reasoner) after %.2f CPU-s", name, spent)
            if on_ready is not None:
                on_ready(offices)
            yield

    app = FastAPI(
        title="AssistantX",
        version="0.1.0",
        description="A proactive office assistant: instructions, live traces, memory, chats.",
        lifespan=lifespan,
        # The stock Swagger UI and ReDoc load their scripts from a CDN and stay blank offline;
        # /docs is our own page (static/docs.html) reading /openapi.json, served from here.
        docs_url=None,
        redoc_url=None,
    )
    app.state.offices = offices
    # One office: its runtime, as before (tests and tools reach it here); several: None.
    app.state.runtime = None if offices.several else offices.slots[offices.home].runtime
    install_error_handlers(app)

    for module in (
        health,
        whoami,
        instructions,
        events,
        memory,
        messages,
        devices,
        metrics,
        dashboard,
        office_routes,
    ):
        app.include_router(module.router)
    app.include_router(reports.router)

    @app.get("/docs", include_in_schema=False)
    async def api_docs() -> FileResponse:
        return FileResponse(STATIC_DIR / "docs.html", media_type="text/html")

    if STATIC_DIR.is_dir():
        app.mount("/", StaticFiles(directory=STATIC_DIR, html=True), name="static")

    def metrics_of(office: str | None) -> ServiceMetrics | None:
        runtime = offices.serving(office)
        return runtime.metrics if runtime is not None else None

    app.add_middleware(RequestMetrics, metrics_of=metrics_of)  # innermost: sees the route
    app.add_middleware(ClientGone)  # a client leaving a stream is no traceback
    app.add_middleware(BodyLimit, max_bytes=settings.max_body_bytes, paths=PATH_BODY_LIMITS)
    app.add_middleware(OfficeRouting)  # /v1/offices/{office}/... reaches the routes
    app.add_middleware(SecurityHeaders)  # also on the body limit's 413
    app.add_middleware(RequestsFirst)  # outermost: instructions wait from a request's arrival
    return app


def _mount_first(app: FastAPI, route: BaseRoute) -> BaseRoute:
    """Mount ``route`` ahead of the others (the static files at "/" take every path they
    reach); returns it, for ``_unmount``."""
    app.router.routes.insert(0, route)
    return route


def _unmount(app: FastAPI, routes: list[BaseRoute]) -> None:
    app.router.routes[:] = [route for route in app.router.routes if route not in routes]
    routes.clear()
