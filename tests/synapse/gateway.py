"""A real uvicorn server on the registered appservice port, routing to whichever router the
current test mounted (or acknowledging and discarding when none is)."""

from __future__ import annotations

import contextlib
import logging
from collections.abc import AsyncIterator
from typing import Any

from fastapi import APIRouter, FastAPI
from starlette.responses import JSONResponse
from starlette.types import Receive, Scope, Send

from assistantx.service.app import PATH_BODY_LIMITS
from assistantx.service.body_limit import BodyLimit
from helpers.servers import serve_asgi

logger = logging.getLogger(__name__)


class AppserviceGateway:
    def __init__(self) -> None:
        self._app: Any = None
        self._down = False
        self.discarded = 0
        self.refused = 0  # requests answered 503 while down

    def mount(self, router: APIRouter) -> None:
        app = FastAPI()
        app.include_router(router)
        # Behind the body limit as the service mounts it (service.app).
        app.add_middleware(BodyLimit, max_bytes=64 * 1024, paths=PATH_BODY_LIMITS)
        self._app = app
        self._down = False

    def mount_app(self, app: Any) -> None:
        """Route everything to a whole ASGI app (its lifespan is the caller's to run)."""
        self._app = app
        self._down = False

    def unmount(self) -> None:
        self._app = None
        self._down = False

    def go_down(self) -> None:
        """Answer 503 to everything, as a restarting service would."""
        self._app = None
        self._down = True

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            return
        if self._app is not None:
            await self._app(scope, receive, send)
            return
        if self._down:
            self.refused += 1
            response = JSONResponse({"errcode": "M_UNKNOWN", "error": "restarting"}, 503)
        else:
            self.discarded += 1
            response = JSONResponse({})
        await response(scope, receive, send)

    @classmethod
    @contextlib.asynccontextmanager
    async def serve(cls, port: int) -> AsyncIterator[AppserviceGateway]:
        gateway = cls()
        async with serve_asgi(gateway, port):
            yield gateway
