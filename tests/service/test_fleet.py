"""The service with several robots (ASSISTANTX_ROBOTS=2): two requests at once go to two
robots, /v1/robots and /metrics show each robot, /v1/robot keeps showing one."""

from __future__ import annotations

from pathlib import Path

import httpx
import pytest

from assistantx.core.settings import Settings
from assistantx.service.fleet_wiring import FleetSettingsError, check_fleet_settings
from assistantx.service.robots import desk_for_code, open_desk
from helpers.eventually import eventually
from helpers.instructions import ended
from service.inprocess import running_service, serving_runtime
from service.server import LEE, OPERATOR, ZHANG

AUTH = {LEE: {"Authorization": f"Bearer {LEE}"}, ZHANG: {"Authorization": f"Bearer {ZHANG}"}}
OP = {"Authorization": f"Bearer {OPERATOR}"}


async def _submit(api: httpx.AsyncClient, token: str, text: str) -> str:
    who = "lee" if token == LEE else "zhang"
    r = await api.post(
        "/v1/instructions", json={"requester": who, "text": text}, headers=AUTH[token]
    )
    assert r.status_code == 202, r.text
    return str(r.json()["id"])


async def test_two_requests_at_once_are_served_by_two_robots(tmp_path: Path) -> None:
    async with running_service(tmp_path / "data", robots=2, speedup=200) as api:
        robots = (await api.get("/v1/robots", headers=OP)).json()
        assert [r["name"] for r in robots] == ["robot 1", "robot 2"]
        assert robots[1]["place"] == "parking 2" and robots[1]["holder"] is None
        one = (await api.get("/v1/robot", headers=OP)).json()
        assert "name" not in one and one["place"] == robots[0]["place"]

        ids = [
            await _submit(api, LEE, "Please bring me a stapler."),
            await _submit(api, ZHANG, "Please bring me a stapler."),
        ]
        holders: set[str] = set()

        async def both_held() -> bool:
            rows = (await api.get("/v1/robots", headers=OP)).json()
            holders.update(r["holder"] for r in rows if r["holder"])
            return len(holders) == 2

        await eventually(both_held, what="each robot held by an instruction", timeout_s=60)
        assert holders == set(ids)  # each instruction holds its own robot

        # Each instruction's own event stream says when it ended (polling both records
        # every 20 ms cost about a CPU-second of requests and serialized traces).
        for iid in ids:
            body = await ended(api, iid, OP, timeout_s=120)
            assert body["status"] == "done", body["summary"]
        rows = (await api.get("/v1/robots", headers=OP)).json()
        assert [r["served"] for r in rows] == [1, 1]
        metrics = (await api.get("/metrics", headers=OP)).text
        assert 'assistantx_robot_instructions_served{robot="robot 2"} 1.0' in metrics
        assert 'assistantx_robot_busy{robot="robot 1"}' in metrics


async def test_one_robot_is_listed_as_robot_1(tmp_path: Path) -> None:
    async with running_service(tmp_path / "data") as api:
        [robot] = (await api.get("/v1/robots", headers=OP)).json()
        assert robot["name"] == "robot 1" and robot["place"] == "meeting_room"
        metrics = (await api.get("/metrics", headers=OP)).text
        assert 'assistantx_robot_busy{robot="robot 1"} 0.0' in metrics


@pytest.mark.parametrize(
    ("settings", "words"),
    [
        ({"robots": 2, "robot": "sim"}, "needs ASSISTANTX_ROBOT=navigator"),
        ({"robots": 2, "lock": "tcp"}, "needs ASSISTANTX_LOCK=local"),
    ],
)
def test_a_fleet_the_settings_cannot_run_is_refused_in_one_line(
    settings: dict[str, object], words: str
) -> None:
    with pytest.raises(FleetSettingsError, match=words):
        check_fleet_settings(Settings(**settings))  # type: ignore[arg-type]


async def test_a_code_is_scanned_at_the_locker_of_the_robot_that_issued_it(tmp_path: Path) -> None:
    async with serving_runtime(tmp_path / "data", robots=2, robot_localize=False) as (_, runtime):
        fleet = runtime.fleet
        assert fleet is not None
        await fleet.lease.acquire("first")  # going nowhere yet: the first free robot, robot 1
        await fleet.lease.acquire("second")  # robot 2
        robot_2 = fleet.lease.body_of("second")
        assert robot_2 is not None and robot_2.name == "robot 2"
        code = await runtime.locker.issue_code(  # this task's robot: the last one given
            instruction_id="second", person="lee", purpose="deposit", item="stapler:lee"
        )
        assert code.lock_id == "locker-1-2"
        desk = await desk_for_code(runtime, code.code_id)
        assert desk is robot_2.locker
        event = await desk.simulate_scan(code.payload)
        assert event.kind == "code_accepted"
        assert await open_desk(runtime) is robot_2.locker  # its door is the open one
        fleet.lease.release("first")
        fleet.lease.release("second")
