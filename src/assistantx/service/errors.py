"""HTTP errors of the API and the one place domain errors become HTTP answers.

Routes raise domain errors (GroundingError, ActionError, ...) or the ``ApiError`` subclasses
below; ``install_error_handlers`` maps each to a status and a JSON body
``{"error": KIND, "message": TEXT}`` that says what is wrong.
"""

from __future__ import annotations

import json
import logging
from typing import TYPE_CHECKING, Any, ClassVar

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

if TYPE_CHECKING:
    from assistantx.store.journal import InstructionRecord, Journal

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


def _body_example(request: Request) -> str | None:
    """The example body of the route that was called, as one line of JSON (from the body
    model's ``json_schema_extra`` examples), so an error can show what to send."""
    route = request.scope.get("route")
    field = getattr(route, "body_field", None)
    model = getattr(getattr(field, "field_info", None), "annotation", None)
    config = getattr(model, "model_config", None) or {}
    extra = config.get("json_schema_extra")
    examples = extra.get("examples") if isinstance(extra, dict) else None
    if not isinstance(examples, list) or not examples:
        return None
    return json.dumps(examples[0])


def _describe_one(error: dict[str, Any], example: str | None) -> str:
    """One validation error in words that say what to send instead."""
    loc = [str(x) for x in error.get("loc", ()) if x != "body"]
    kind = error.get("type")
    send = f"send a JSON object such as {example}" if example else "send a JSON object"
    if kind == "json_invalid":
        # FastAPI reports where the decoder stopped ("26: JSON decode error" by default)
        at = error.get("loc", ("body", "?"))[-1]
        return f"the body is not valid JSON (it stops making sense at character {at}): {send}"
    if not loc and kind in ("model_attributes_type", "dict_type", "missing"):
        return (
            "the body must be a JSON object with the header Content-Type: application/json: " + send
        )
    name = ".".join(loc) or "body"
    context = error.get("ctx") or {}
    if kind == "string_too_short" and context.get("min_length") == 1:
        return f"{name} must not be blank"
    if kind == "missing":
        return f"{name} is missing: {send}"
    if kind == "extra_forbidden":
        return f"{name} is not a field of this request: {send}"
    return f"{name}: {error.get('msg')}"


def _describe(errors: list[dict[str, Any]], example: str | None = None) -> str:
    return "; ".join(_describe_one(e, example) for e in errors[:5])


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
        message = _describe(errors, _body_example(request))
        return JSONResponse(error_body("invalid_request", message, detail=detail), status_code=422)

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


def unknown_instruction(instruction_id: str) -> NotFoundError:
    """The one answer for an instruction that is not there (or not the caller's to see)."""
    return NotFoundError(f"no instruction {instruction_id!r}")


def journaled_instruction(journal: Journal, instruction_id: str) -> InstructionRecord:
    """An instruction's record from the journal, or ``unknown_instruction``."""
    record = journal.instruction(instruction_id)
    if record is None:
        raise unknown_instruction(instruction_id)
    return record
