"""The Matrix application-service pushes of several offices: every office's homeserver pushes
to the same ``/_matrix/app/v1/...`` paths, told apart by the homeserver token; each reaches its
own office, also one a replica takes over after its start-up, and an office that left a
replica is answered 503 there (the homeserver retries), never a 200 that drops the events.

Real uvicorn servers and the tests' PostgreSQL; no homeserver: the test PUTs the
transactions a homeserver would (in push mode with no groups the messengers send nothing)."""

from __future__ import annotations

from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Any

import httpx
import pytest
import yaml

from adapters.messenger.conftest import PUSH_YAML
from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from assistantx.service.offices.deployment import DeploymentError, load_deployment
from assistantx.service.offices.directory import Offices
from helpers.eventually import eventually
from helpers.servers import serving_app
from service.server import OPERATOR
from service.test_offices import DEPLOYMENT

OFFICES = ("hq", "harbour")
TOKENS = {"hq": "hs-token-of-hq", "harbour": "hs-token-of-harbour"}
TTL_S = 3.0  # a balancer round every second


def _deployment(folder: Path) -> Path:
    """The two offices of test_offices, each with its Matrix messenger in push mode and a
    homeserver token of its own (and nobody on Matrix: the pushed events start nothing)."""
    offices = []
    for entry in DEPLOYMENT["offices"]:
        config = folder / f"matrix-{entry['id']}.yaml"
        config.write_text(
            PUSH_YAML.replace("as-token", f"as-token-of-{entry['id']}")
            .replace("hs-token", TOKENS[entry["id"]])
            .replace('people: {lee: "@lee:office.test"}', "people: {}"),
            encoding="utf-8",
        )
        offices.append({**entry, "messenger": "matrix", "matrix_config": str(config)})
    path = folder / "offices.yaml"
    path.write_text(yaml.safe_dump({"offices": offices}), encoding="utf-8")
    return path


def _settings(folder: Path, data: str, **extra: Any) -> Settings:
    return Settings(
        data_dir=folder / data,
        offices=_deployment(folder),
        operator_token=OPERATOR,
        speedup=50,
        robot="sim",
        people="human",
        **extra,
    )


@asynccontextmanager
async def _serving(settings: Settings) -> AsyncIterator[tuple[httpx.AsyncClient, Offices]]:
    app = create_app(settings)
    async with serving_app(app) as api:
        yield api, app.state.offices


async def _push(api: httpx.AsyncClient, txn: str, token: str | None) -> httpx.Response:
    headers = {} if token is None else {"Authorization": f"Bearer {token}"}
    event = {"type": "m.room.topic", "event_id": f"${txn}", "room_id": "!r:office.test"}
    return await api.put(
        f"/_matrix/app/v1/transactions/{txn}", json={"events": [event]}, headers=headers
    )


async def _seen(offices: Offices, office: str, txn: str) -> bool:
    runtime = offices.serving(office)
    assert runtime is not None and runtime.matrix is not None
    return await runtime.matrix.store.transaction_seen(txn)


async def test_each_office_gets_the_pushes_with_its_own_token(tmp_path: Path) -> None:
    async with _serving(_settings(tmp_path, "data")) as (api, offices):
        for office in OFFICES:
            r = await _push(api, f"t-{office}", TOKENS[office])
            assert r.status_code == 200, r.text
        for office in OFFICES:  # each transaction reached its office only
            other = next(o for o in OFFICES if o != office)
            assert await _seen(offices, office, f"t-{office}")
            assert not await _seen(offices, office, f"t-{other}")
        assert (await _push(api, "t-x", "not-a-homeserver-token")).status_code == 403
        assert (await _push(api, "t-y", None)).status_code == 401


@pytest.mark.postgres  # two replicas sharing the tests' PostgreSQL (postgres_url)
async def test_an_office_taken_over_later_gets_its_pushes_and_leaves_a_503(
    tmp_path: Path, postgres_url: str
) -> None:
    shared = {"database_url": postgres_url, "lease_ttl_s": TTL_S}
    a_settings = _settings(tmp_path, "a", replica_id="a", **shared)
    async with _serving(a_settings) as (a_api, a):
        await eventually(
            lambda: all(a.serving(o) for o in OFFICES), what="A to run both", timeout_s=60
        )
        for office in OFFICES:
            assert (await _push(a_api, f"a-{office}", TOKENS[office])).status_code == 200

        async with _serving(_settings(tmp_path, "b", replica_id="b", **shared)) as (b_api, b):
            # B starts with both offices held by A: whatever it runs later, it takes over
            # after its start-up (a balancer round), when A hands its surplus back.
            assert not any(b.serving(o) for o in OFFICES)
            moved = await eventually(
                lambda: next((o for o in OFFICES if b.serving(o)), None),
                what="B to take one office over",
                timeout_s=60,
            )
            kept = next(o for o in OFFICES if o != moved)
            await eventually(lambda: a.serving(moved) is None, what="A to stop it", timeout_s=30)

            r = await _push(b_api, "b-moved", TOKENS[moved])
            assert r.status_code == 200, r.text
            assert await _seen(b, moved, "b-moved")

            stale = await _push(a_api, "a-moved", TOKENS[moved])
            assert stale.status_code == 503, stale.text  # the homeserver retries it
            assert stale.json()["errcode"] == "M_UNKNOWN"
            assert (await _push(a_api, "a-kept", TOKENS[kept])).status_code == 200
            assert await _seen(a, kept, "a-kept")
            # B never ran the other office: its token is none of B's offices'.
            assert (await _push(b_api, "b-kept", TOKENS[kept])).status_code == 403


@pytest.mark.parametrize("shared", ["hs-token", "as-token"])
def test_two_offices_with_one_registration_token_are_refused_in_one_line(
    tmp_path: Path, shared: str
) -> None:
    path = _deployment(tmp_path)
    harbour = tmp_path / "matrix-harbour.yaml"
    hq_text = (tmp_path / "matrix-hq.yaml").read_text(encoding="utf-8")
    if shared == "hs-token":
        harbour.write_text(hq_text, encoding="utf-8")  # the same file's tokens: both shared
    else:
        # only the application-service token is the other office's
        harbour_text = harbour.read_text(encoding="utf-8")
        harbour.write_text(
            harbour_text.replace("as-token-of-harbour", "as-token-of-hq"), encoding="utf-8"
        )
    with pytest.raises(DeploymentError) as caught:
        load_deployment(Settings(offices=path))
    message = str(caught.value)
    assert message.startswith(str(path)) and "\n" not in message
    assert "'hq' and 'harbour'" in message and shared.replace("-", "_") in message
    assert "token-of" not in message  # no secret shown


def test_offices_with_their_own_registrations_load(tmp_path: Path) -> None:
    specs = load_deployment(Settings(offices=_deployment(tmp_path)))
    assert [s.id for s in specs] == list(OFFICES)
