"""Matrix in the service's one composition root: the config is checked at ``create_app`` (and
nothing is opened there); ``ServiceRuntime.start`` builds the messenger with the journal as its
transcript, starts it after the Assistant and mounts its push routes; every way out of the
lifespan (a clean stop, a start that fails later) stops it and closes its store.

The homeserver is a closed port: in push mode with no groups the messenger's start asks it
nothing, and these tests send nothing out."""

from __future__ import annotations

import functools
import json
from pathlib import Path
from typing import Any

import pytest

from adapters.messenger.conftest import PUSH_YAML
from assistantx.adapters.lock.protocol import client as lock_client
from assistantx.adapters.lock.protocol.link import LinkTimeouts
from assistantx.core.errors import LockConnectionError, MessengerError
from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from helpers.servers import free_port, serving_app
from service.server import LEE, OPERATOR

HS = {"Authorization": "Bearer hs-token"}
PUSH = "/_matrix/app/v1/transactions/t1"


def _settings(tmp_path: Path, matrix_yaml: str = PUSH_YAML, **extra: Any) -> Settings:
    config = tmp_path / "matrix.yaml"
    config.write_text(matrix_yaml, encoding="utf-8")
    fields: dict[str, Any] = {
        "data_dir": tmp_path / "data",
        "messenger": "matrix",
        "matrix_config": config,
        "operator_token": OPERATOR,
        "tokens": json.dumps({LEE: "lee"}),
        "speedup": 50,
        "robot": "sim",
        "people": "human",
    }
    return Settings(**(fields | extra))


def _push_routes(app: Any) -> list[str]:
    return [r.path for r in app.router.routes if getattr(r, "path", "").startswith("/_matrix")]


def test_create_app_checks_the_config_and_opens_nothing(tmp_path: Path) -> None:
    with pytest.raises(MessengerError, match="needs pull_user_id"):
        create_app(_settings(tmp_path, PUSH_YAML.replace("mode: push", "mode: pull")))
    app = create_app(_settings(tmp_path))
    assert app.state.runtime.matrix is None  # built by the runtime's start
    assert not (tmp_path / "data" / "matrix.sqlite3").exists()
    assert _push_routes(app) == []


async def test_the_runtime_builds_starts_mounts_and_closes_matrix(tmp_path: Path) -> None:
    app = create_app(_settings(tmp_path))
    async with serving_app(app) as api:
        runtime = app.state.runtime
        matrix = runtime.matrix
        assert matrix.messenger.started
        assert matrix.messenger.transcript is runtime.journal
        assert runtime.assistant.parts.messenger is matrix.messenger
        assert (await api.put(PUSH, json={"events": []}, headers=HS)).status_code == 200
        wrong = await api.put(PUSH, json={"events": []}, headers={"Authorization": "Bearer x"})
        assert wrong.status_code == 403  # the appservice route, not the static files
    assert not matrix.messenger.started
    with pytest.raises(MessengerError, match="closed"):
        await matrix.store.unhandled()
    assert _push_routes(app) == []  # a later lifespan mounts its own messenger's routes


async def test_a_start_that_fails_after_matrix_is_built_still_closes_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The lock's client gives up on a port nobody listens on after connect_s (5 s by default,
    # waited out in full): half a second shows the same failure.
    monkeypatch.setattr(lock_client, "LinkTimeouts", functools.partial(LinkTimeouts, connect_s=0.5))
    nobody_listens = free_port()
    app = create_app(_settings(tmp_path, lock="tcp", lock_port=nobody_listens))
    with pytest.raises(LockConnectionError, match=r"within 0\.5 s"):
        async with app.router.lifespan_context(app):
            pass
    matrix = app.state.runtime.matrix
    assert matrix is not None and not matrix.messenger.started
    with pytest.raises(MessengerError, match="closed"):
        await matrix.store.unhandled()
