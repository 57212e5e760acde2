"""The app's route tables, built before the service is ready instead of at its first requests.

FastAPI (0.165, pinned) builds an included router's table the first time a request is matched
against it: every endpoint's dependencies and parameters are analysed then, on the event loop
(49 ms of the loop's own CPU in one callback at the first request under
bench/service_load.py, the longest of its stalls in that run). ``build_route_tables`` makes
FastAPI build them now, on a worker thread (FastAPI guards the build with a lock of its own).
It reaches FastAPI's included-router objects by duck typing, ``effective_candidates``: where a
FastAPI version has no such method, nothing is built and the first requests pay as before.

``import_thread_backend`` likewise imports anyio's asyncio back end, which the first request
with a dependency run in the thread pool (an event stream's replay reads) imported on the loop:
41 ms of the loop's CPU in one callback, at the bench's first event stream.
"""

from __future__ import annotations

import importlib
import logging
from typing import Any

from fastapi import FastAPI

logger = logging.getLogger(__name__)


def build_route_tables(app: FastAPI) -> int:
    """Build every included router's table (nested ones too); how many were built."""
    pending: list[Any] = list(app.router.routes)
    built = 0
    while pending:
        route = pending.pop()
        for method in ("effective_candidates", "effective_low_priority_routes"):
            build = getattr(route, method, None)
            if callable(build):
                candidates = build()
                if method == "effective_candidates":
                    built += 1
                    pending.extend(candidates)
    logger.debug("%d route tables built", built)
    return built


def import_thread_backend() -> None:
    """anyio's asyncio back end (``anyio.to_thread`` loads it at its first use), imported here
    so that its first use finds it loaded."""
    importlib.import_module("anyio._backends._asyncio")
