"""The application-service endpoints the homeserver pushes to (Matrix AS API v1).

``create_appservice_router`` returns a FastAPI ``APIRouter`` for the service to mount:

- ``PUT /_matrix/app/v1/transactions/{txnId}``: a batch of events. A transaction already
  accepted is acknowledged without effect; otherwise its events go through the ingestor
  (durably stored, then queued) and only then is it acknowledged with ``200 {}``. Any failure
  answers 500, so the homeserver retries the same transaction later. Transactions are taken
  in one at a time, in arrival order. An event that raises is skipped alone and counted (see
  ``ingest``); a body nested too deep to parse is acknowledged, logged and counted, never
  answered with an error the homeserver would retry for ever.
- ``POST /_matrix/app/v1/ping``: answers ``{}`` (the homeserver's connectivity check).
- ``GET /_matrix/app/v1/users/{userId}`` and ``/rooms/{alias}``: we create no users or rooms
  on demand, so ``404 M_NOT_FOUND``.

Every endpoint checks the homeserver token, sent as ``Authorization: Bearer`` (or the legacy
``?access_token=``), in constant time. As the AS API specifies: no token → ``401
M_UNAUTHORIZED``; a wrong token → ``403 M_FORBIDDEN``.

The size of a push is capped by the host's one request-size limit (the service's
``BodyLimit``), configured with ``PUSH_PATH_PREFIX``, ``MAX_PUSH_BODY_BYTES`` and
``push_too_large_error`` from here: a body over it is refused with ``413 M_TOO_LARGE`` before
it is read.
"""

from __future__ import annotations

import hmac
import json
import logging
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import JSONResponse
from pydantic import SecretStr

from assistantx.adapters.messenger.matrix.ingest import EventIngestor, RoomEvent

logger = logging.getLogger(__name__)

PUSH_PATH_PREFIX = "/_matrix/app/"
"""Every endpoint the homeserver pushes to is under this path."""

MAX_PUSH_BODY_BYTES = 16 * 1024 * 1024
"""Synapse batches at most 100 events (each at most 64 KiB) plus ephemeral data."""


def matrix_error(status: int, errcode: str, error: str) -> JSONResponse:
    return JSONResponse({"errcode": errcode, "error": error}, status_code=status)


def push_too_large_error(limit_bytes: int) -> dict[str, str]:
    """The body of a 413 to the homeserver, in the Matrix error format it reads."""
    return {"errcode": "M_TOO_LARGE", "error": f"the request body exceeds {limit_bytes} bytes"}


def presented_token(request: Request) -> str | None:
    """The homeserver token a push presents; None without one ("" for a malformed header)."""
    header = request.headers.get("authorization")
    if header is not None:
        scheme, _, token = header.partition(" ")
        if scheme.lower() == "bearer" and token:
            return token.strip()
        return ""  # a malformed header is a wrong token, not a missing one
    return request.query_params.get("access_token")


def _authenticate(request: Request, hs_token: SecretStr) -> JSONResponse | None:
    presented = presented_token(request)
    if presented is None:
        return unauthorized()
    if not token_matches(presented, hs_token):
        logger.warning("refused a push with a wrong homeserver token from %s", request.client)
        return forbidden()
    return None


def token_matches(presented: str, hs_token: SecretStr) -> bool:
    """Whether ``presented`` is ``hs_token``, compared in constant time."""
    return hmac.compare_digest(presented.encode(), hs_token.get_secret_value().encode())


def unauthorized() -> JSONResponse:
    return matrix_error(401, "M_UNAUTHORIZED", "missing homeserver token")


def forbidden() -> JSONResponse:
    return matrix_error(403, "M_FORBIDDEN", "invalid homeserver token")


def _room_events(body: Any) -> list[RoomEvent] | None:
    if not isinstance(body, dict):
        return None
    events = body.get("events", [])
    if not isinstance(events, list):
        return None
    pairs: list[RoomEvent] = []
    for event in events:
        if isinstance(event, dict) and isinstance(event.get("room_id"), str):
            pairs.append((event["room_id"], event))
    return pairs


def create_appservice_router(*, hs_token: SecretStr, ingestor: EventIngestor) -> APIRouter:
    """The AS endpoints; ``ingestor`` holds the store, the normalizer and the inbox."""
    router = APIRouter(tags=["matrix-appservice"])

    @router.put("/_matrix/app/v1/transactions/{txn_id}")
    async def push_transaction(txn_id: str, request: Request) -> JSONResponse:
        refused = _authenticate(request, hs_token)
        if refused is not None:
            return refused
        body = await request.body()
        try:
            events = _room_events(json.loads(body))
        except ValueError:
            events = None
        except RecursionError as exc:
            # Nested deeper than Python's parser goes. A homeserver never sends this (it
            # parses events the same way); answering anything but 200 would make it retry
            # the transaction for ever and queue every later one behind it.
            ingestor.skipped.skip("matrix_push", f"transaction {txn_id}", "parsing", exc)
            return JSONResponse({})
        if events is None:
            return matrix_error(400, "M_NOT_JSON", "a transaction is a JSON object with events")
        try:
            if await ingestor.store.transaction_seen(txn_id):
                logger.debug("transaction %s already accepted", txn_id)
                return JSONResponse({})
            fresh = await ingestor.ingest(events, txn_id=txn_id)
        except Exception:
            logger.exception("transaction %s failed; the homeserver will retry it", txn_id)
            return matrix_error(500, "M_UNKNOWN", "transaction not accepted; retry later")
        logger.debug("transaction %s: %d events, %d new messages", txn_id, len(events), len(fresh))
        return JSONResponse({})

    @router.post("/_matrix/app/v1/ping")
    async def ping(request: Request) -> JSONResponse:
        refused = _authenticate(request, hs_token)
        return refused if refused is not None else JSONResponse({})

    @router.get("/_matrix/app/v1/users/{user_id}")
    async def query_user(user_id: str, request: Request) -> JSONResponse:
        refused = _authenticate(request, hs_token)
        if refused is not None:
            return refused
        return matrix_error(404, "M_NOT_FOUND", "no users are created on demand")

    @router.get("/_matrix/app/v1/rooms/{alias}")
    async def query_room(alias: str, request: Request) -> JSONResponse:
        refused = _authenticate(request, hs_token)
        if refused is not None:
            return refused
        return matrix_error(404, "M_NOT_FOUND", "no rooms are created on demand")

    return router


def create_discarding_router(*, hs_token: SecretStr) -> APIRouter:
    """For ``pull`` mode: a registration left from ``push`` mode still pushes; acknowledge and
    drop (the poller receives the same events), and say once in the log what to do."""
    router = APIRouter(tags=["matrix-appservice"])
    warned = False

    @router.put("/_matrix/app/v1/transactions/{txn_id}")
    async def push_transaction(txn_id: str, request: Request) -> JSONResponse:
        nonlocal warned
        refused = _authenticate(request, hs_token)
        if refused is not None:
            return refused
        if not warned:
            warned = True
            logger.warning(
                "the homeserver still pushes to us in pull mode; the pushes are dropped "
                "(the /sync poller receives everything). Remove the appservice registration "
                "from the homeserver, or use mode 'both'."
            )
        return JSONResponse({})

    @router.post("/_matrix/app/v1/ping")
    async def ping(request: Request) -> JSONResponse:
        refused = _authenticate(request, hs_token)
        return refused if refused is not None else JSONResponse({})

    return router
