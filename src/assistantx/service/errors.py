"""HTTP errors of the API and the one place domain errors become HTTP answers.

Routes raise domain errors (GroundingError, ActionError, ...) or the ``ApiError`` subclasses
below; ``install_error_handlers`` maps each to a status and a JSON body
``{"error": KIND, "message": TEXT}`` that says what is wrong.
"""

from __future__ import annotations

import logging
from typing import ClassVar

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from starlette.exceptions import HTTPException as StarletteHTTPException

from assistantx.core.errors import (
    ActionError,
    AdapterError,
    AmbiguousNameError,
    AssistantXError,
    GroundingError,
)

logger = logging.getLogger(__name__)


class ApiError(Exception):
    status = 400
    kind = "bad_request"
    headers: ClassVar[dict[str, str] | None] = None

    def __init__(self, message: str) -> None:
        self.message = message
        super().__init__(message)


class UnauthorizedError(ApiError):
    status = 401
    kind = "unauthorized"
    headers: ClassVar[dict[str, str] | None] = {"WWW-Authenticate": 'Bearer realm="assistantx"'}


class ForbiddenError(ApiError):
    status = 403
    kind = "forbidden"


class NotFoundError(ApiError):
    status = 404
    kind = "not_found"


class ConflictError(ApiError):
    status = 409
    kind = "conflict"


class PayloadTooLargeError(ApiError):
    status = 413
    kind = "payload_too_large"


class UnprocessableError(ApiError):
    status = 422
    kind = "unprocessable"


class TooManyRequestsError(ApiError):
    status = 429
    kind = "too_many_requests"


class UnavailableError(ApiError):
    status = 503
    kind = "unavailable"


def error_body(kind: str, message: str, **extra: object) -> dict[str, object]:
    return {"error": kind, "message": message, **extra}


def _status_of(exc: AssistantXError) -> tuple[int, str]:
    if isinstance(exc, AmbiguousNameError):
        return 422, "ambiguous_name"
    if isinstance(exc, GroundingError):
        return 422, "unknown_name"
    if isinstance(exc, ActionError):
        return 409, "invalid_action"
    if isinstance(exc, AdapterError):
        return 502, "adapter_error"
    return 500, "internal_error"


def _describe(errors: list[dict[str, object]]) -> str:
    parts = []
    for e in errors[:5]:
        loc = ".".join(str(x) for x in e.get("loc", ()) if x != "body")  # type: ignore[attr-defined]
        parts.append(f"{loc or 'body'}: {e.get('msg')}")
    return "; ".join(parts)


def install_error_handlers(app: FastAPI) -> None:
    async def api_error(request: Request, exc: Exception) -> JSONResponse:
        assert isinstance(exc, ApiError)
        return JSONResponse(
            error_body(exc.kind, exc.message), status_code=exc.status, headers=exc.headers
        )

    async def domain_error(request: Request, exc: Exception) -> JSONResponse:
        assert isinstance(exc, AssistantXError)
        status, kind = _status_of(exc)
        if status >= 500:
            logger.warning("request %s failed: %s", request.url.path, exc)
        extra: dict[str, object] = {}
        if isinstance(exc, GroundingError):
            extra = {"kind_of_name": exc.kind, "name": exc.name, "candidates": exc.candidates}
        return JSONResponse(error_body(kind, str(exc), **extra), status_code=status)

    async def validation_error(request: Request, exc: Exception) -> JSONResponse:
        assert isinstance(exc, RequestValidationError)
        errors = [dict(e) for e in exc.errors()]
        detail = [
            {"loc": list(e.get("loc", ())), "msg": e.get("msg"), "type": e.get("type")}
            for e in errors
        ]
        return JSONResponse(
            error_body("invalid_request", _describe(errors), detail=detail), status_code=422
        )

    async def http_error(request: Request, exc: Exception) -> JSONResponse:
        assert isinstance(exc, StarletteHTTPException)
        kind = {404: "not_found", 405: "method_not_allowed"}.get(exc.status_code, "http_error")
        return JSONResponse(
            error_body(kind, str(exc.detail)), status_code=exc.status_code, headers=exc.headers
        )

    app.add_exception_handler(ApiError, api_error)
    app.add_exception_handler(AssistantXError, domain_error)
    app.add_exception_handler(RequestValidationError, validation_error)
    app.add_exception_handler(StarletteHTTPException, http_error)
