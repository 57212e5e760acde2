"""The service app in this process, served by a real uvicorn server on 127.0.0.1, as a
context manager (for tests that restart it on the same data folder or vary its settings)."""

from __future__ import annotations

import json
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Any

import httpx
from fastapi import FastAPI

from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from assistantx.service.runtime import ServiceRuntime
from helpers.eventually import eventually
from helpers.servers import serving_app
from service.server import LEE, OPERATOR, ZHANG


def _settings(data_dir: Path, **settings: Any) -> Settings:
    """The tests' defaults (the operator's and two colleagues' tokens, speed-up 50, no AMCL)
    with ``settings`` over them."""
    defaults: dict[str, Any] = {
        "data_dir": data_dir,
        "operator_token": OPERATOR,
        "tokens": json.dumps({LEE: "lee", ZHANG: "zhang"}),
        "speedup": 50,
        "robot_localize": False,
    }
    return Settings(**{**defaults, **settings})


@asynccontextmanager
async def running_service(data_dir: Path, **settings: Any) -> AsyncIterator[httpx.AsyncClient]:
    """A client of a fresh server; ``settings`` override the tests' defaults (speed-up 50; the
    navigator without AMCL, i.e. kinematic paths on the map: a test of localization passes
    ``robot_localize=True``)."""
    app = create_app(_settings(data_dir, **settings))
    async with serving_app(app) as client:
        await _holding(app)
        yield client


@asynccontextmanager
async def serving_runtime(
    data_dir: Path, **settings: Any
) -> AsyncIterator[tuple[httpx.AsyncClient, ServiceRuntime]]:
    """Like ``running_service`` (the operator's token on every request; no AMCL unless
    ``robot_localize=True``), also yielding the runtime: for tests that play the physical
    world (a person holding a code up to the lock)."""
    app = create_app(_settings(data_dir, **settings))
    headers = {"Authorization": f"Bearer {OPERATOR}"}
    async with serving_app(app, headers=headers) as client:
        await _holding(app)
        yield client, app.state.runtime


async def _holding(app: FastAPI) -> None:
    """One office on a database answers as a standby at once; tests of the office want it
    run here: wait until it holds the office's lease and its assistant runs (a replica
    started while another holds the office waits here, as a standby does)."""
    offices = app.state.offices
    if offices.several or offices.leases is None:
        return
    await eventually(
        lambda: offices.serving(None), what="this replica to run the office", timeout_s=120
    )
