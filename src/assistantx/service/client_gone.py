"""A client that leaves a stream mid-way is normal, not an error of the app.

FastAPI's event-stream response pumps the route's events through a memory stream and a
keep-alive task. When the reader is gone and the response is torn down while that task still
holds an event to pass on, the task fails with ``anyio.BrokenResourceError``, and its task
group raises it, in an exception group, through every middleware into uvicorn's log as
"Exception in ASGI application". ``ClientGone`` answers it the way it should be: once the
response has started, a broken or closed stream means the client left; one debug line, no
traceback. Before the response started it is a real failure and goes on up.
"""

from __future__ import annotations

import logging

import anyio
from starlette.types import ASGIApp, Message, Receive, Scope, Send

logger = logging.getLogger(__name__)


class ClientGone:
    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        started = False

        async def tracking_send(message: Message) -> None:
            nonlocal started
            started = started or message["type"] == "http.response.start"
            await send(message)

        try:
            await self.app(scope, receive, tracking_send)
        except* (anyio.BrokenResourceError, anyio.ClosedResourceError):
            if not started:
                raise
            logger.debug("the client left %s before its stream ended", scope.get("path"))
