"""Office-scoped URLs: ``/v1/offices/{office}/...`` is the route ``/v1/...`` of that office.

The routes are written once, for one office; this ASGI middleware strips the office from the
path and leaves its id in the request's scope (``OFFICE_KEY``), where ``deps.get_runtime`` and
``deps.get_principal`` read it. A path without an office addresses the home office (the first
one), so a single-office deployment's URLs work unchanged. ``/v1/offices/{office}/metrics``
and ``.../readyz`` are that office's ``/metrics`` and ``/readyz``.
"""

from __future__ import annotations

from starlette.types import ASGIApp, Receive, Scope, Send

OFFICE_KEY = "assistantx.office"
PREFIX = "/v1/offices/"
TOP_LEVEL = frozenset({"metrics", "readyz"})  # routes outside /v1


def office_of(scope: Scope) -> str | None:
    """The office a request addresses; None: the home office."""
    office = scope.get(OFFICE_KEY)
    return office if isinstance(office, str) else None


class OfficeRouting:
    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] in ("http", "websocket"):
            path: str = scope["path"]
            if path.startswith(PREFIX):
                office, slash, rest = path[len(PREFIX) :].partition("/")
                if office and slash and rest:
                    first = rest.partition("/")[0]
                    inner = f"/{rest}" if first in TOP_LEVEL else f"/v1/{rest}"
                    scope = {**scope, "path": inner, "raw_path": inner.encode(), OFFICE_KEY: office}
        await self.app(scope, receive, send)
