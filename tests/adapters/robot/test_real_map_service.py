"""The service on a real building's map (nav2's depot map) with AMCL on: an instruction
reaches done; with the way to the requester truly blocked, it ends with the requester told
where the robot and the item in its locker are."""

from __future__ import annotations

import json
from collections.abc import AsyncIterator
from pathlib import Path
from typing import Any

import httpx
import numpy as np
import pytest

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.office import load_office
from assistantx.core.settings import Settings
from assistantx.nav.anchor_check import place_anchors
from assistantx.nav.anchors import save_anchors
from assistantx.nav.costmap import Costmap
from assistantx.nav.occupancy_map import load_map
from assistantx.service.app import create_app
from helpers.instructions import ended
from helpers.maps import real_map
from helpers.servers import serving_app
from service.server import LEE, OPERATOR

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow

AUTH_LEE = {"Authorization": f"Bearer {LEE}"}
AUTH_OP = {"Authorization": f"Bearer {OPERATOR}"}


def _office_anchors_on(map_yaml: Path, out: Path) -> Path:
    """Anchors for every office location, spread over the map's reachable free space."""
    office = load_office()
    placed = place_anchors(
        Costmap.inflate(load_map(map_yaml)), len(office.locations), np.random.default_rng(11)
    )
    save_anchors(dict(zip((loc.id for loc in office.locations), placed.values(), strict=True)), out)
    return out


@pytest.fixture
async def depot_service(tmp_path: Path) -> AsyncIterator[tuple[httpx.AsyncClient, Any]]:
    map_yaml = real_map("depot")
    settings = Settings(
        data_dir=tmp_path / "data",
        operator_token=OPERATOR,
        tokens=json.dumps({LEE: "lee"}),
        speedup=20,
        map=map_yaml,
        map_anchors=_office_anchors_on(map_yaml, tmp_path / "depot.anchors.yaml"),
    )
    app = create_app(settings)
    async with serving_app(app, timeout=30) as client:
        yield client, app.state.runtime


async def _finished(client: httpx.AsyncClient, iid: str) -> dict[str, Any]:
    return await ended(client, iid, AUTH_LEE, timeout_s=180)


async def _submit(client: httpx.AsyncClient) -> str:
    r = await client.post(
        "/v1/instructions",
        json={"requester": "lee", "text": "Please bring me a stapler."},
        headers=AUTH_LEE,
    )
    assert r.status_code == 202, r.text
    return str(r.json()["id"])


async def _told_lee(client: httpx.AsyncClient) -> list[str]:
    chat = (await client.get("/v1/chats/dm/lee", headers=AUTH_OP)).json()
    return [str(m["text"]) for m in chat if m["direction"] == "out"]


async def test_instruction_reaches_done_on_a_real_map(
    depot_service: tuple[httpx.AsyncClient, Any],
) -> None:
    client, runtime = depot_service
    robot = runtime.sim.robot.base
    assert isinstance(robot, NavigatorRobot) and robot.localize
    body = await _finished(client, await _submit(client))
    assert (body["status"], body["outcome"]) == ("done", "done"), body.get("summary")
    assert robot.navigator.base.odometer_m > 5.0  # it really drove on the depot map
    assert robot.state().place == load_office().person("lee").location


async def test_truly_blocked_way_ends_with_the_requester_told(
    depot_service: tuple[httpx.AsyncClient, Any],
) -> None:
    client, runtime = depot_service
    robot = runtime.sim.robot.base
    assert isinstance(robot, NavigatorRobot)
    office = load_office()
    desk = robot.anchors[office.person("lee").location]
    robot.block(desk.x, desk.y, 0.8)  # something stands on Lee's desk spot for good
    body = await _finished(client, await _submit(client))
    assert body["outcome"] == "failed"
    told = [t for t in await _told_lee(client) if not t.startswith("A short survey")]
    last = told[-1]
    assert "stapler" in last and "locked in its locker" in last, last
    lee_place = office.location(office.person("lee").location).name
    assert lee_place in last
    # The locker's contents are accounted for: the stapler is still in it.
    assert any(i.startswith("stapler:") for i in runtime.sim.world.locker_contents())
