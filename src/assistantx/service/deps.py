"""Request dependencies: the runtime and the authenticated caller."""

from __future__ import annotations

from typing import Annotated

from fastapi import Depends, Request

from assistantx.service.auth import Principal
from assistantx.service.errors import UnavailableError
from assistantx.service.runtime import ServiceRuntime


def get_runtime(request: Request) -> ServiceRuntime:
    runtime: ServiceRuntime | None = getattr(request.app.state, "runtime", None)
    if runtime is None or not runtime.ready:
        raise UnavailableError("the assistant is starting or stopping; try again shortly")
    return runtime


Runtime = Annotated[ServiceRuntime, Depends(get_runtime)]


def get_principal(request: Request, runtime: Runtime) -> Principal:
    return runtime.auth.authority.authenticate(request.headers.get("authorization"))


Caller = Annotated[Principal, Depends(get_principal)]
