"""The Matrix push endpoints of the offices this process runs, behind one route.

Every office's homeserver registration pushes to the same paths (``/_matrix/app/v1/...``
under the service's address); only the homeserver token (``hs_token``) each registration
holds tells them apart. So the app mounts one ``OfficePushes`` (ahead of the static files,
when the first office with a Matrix messenger starts here) and ``add``s each office's push
routes when it starts, at start-up or later, when the balancer takes an office over. A push
goes to the office whose token it presents:

- that office runs here: its messenger's routes answer (200 once the events are stored);
- it ran here and stopped (it moved to another replica, or this process is stopping):
  ``503 M_UNKNOWN``, never a 200 that would drop the events: the homeserver retries the
  transaction later (through a load balancer, possibly on the replica that runs it now);
- no office here has that token: ``401 M_UNAUTHORIZED`` without a token, ``403 M_FORBIDDEN``
  with another one, as the application-service API specifies.

A newer runtime of an office replaces a stopped one's routes. Two offices sharing one token
are refused when the deployment file is read (``offices.deployment``).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

from fastapi import APIRouter, Request
from starlette.types import Receive, Scope, Send

from assistantx.adapters.messenger.matrix.appservice import (
    forbidden,
    matrix_error,
    presented_token,
    token_matches,
    unauthorized,
)
from assistantx.service.runtime import ServiceRuntime

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class _OfficePush:
    runtime: ServiceRuntime
    router: APIRouter  # built once: in pull mode each build is a new discarding router


class OfficePushes:
    """An ASGI app answering every path under ``/_matrix/app/`` for the offices added."""

    def __init__(self) -> None:
        self._offices: dict[str, _OfficePush] = {}

    def add(self, office_id: str, runtime: ServiceRuntime) -> bool:
        """``office_id`` runs ``runtime`` here from now on; False when it has no Matrix
        messenger (nothing to push to)."""
        if runtime.matrix is None:
            return False
        self._offices[office_id] = _OfficePush(runtime, runtime.matrix.push_router)
        return True

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        presented = presented_token(Request(scope))
        if presented is None:
            await unauthorized()(scope, receive, send)
            return
        owners = [
            (office_id, push)
            for office_id, push in self._offices.items()
            if push.runtime.matrix is not None
            and token_matches(presented, push.runtime.matrix.config.hs_token)
        ]
        running = [push for _, push in owners if push.runtime.ready]
        if running:
            await running[0].router(scope, receive, send)
        elif owners:
            logger.info("a push for office %s, which no longer runs here: 503", owners[0][0])
            stopped = matrix_error(503, "M_UNKNOWN", "the office does not run here; retry later")
            await stopped(scope, receive, send)
        else:
            logger.warning(
                "refused a push with no office's homeserver token from %s", scope.get("client")
            )
            await forbidden()(scope, receive, send)
