"""The simulated office with other adapters: the navigator base and a TCP locker, and what
simulated people forget when an instruction ends."""

from __future__ import annotations

from collections.abc import AsyncIterator

import pytest

from assistantx.adapters.lock.protocol import LockKeys
from assistantx.adapters.lock.tcp import TcpLocker
from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.actions import Inform, Inquire, Move, SendQR, Wait, WaitInPlace
from assistantx.core.clock import SimClock, WallClock
from assistantx.core.office import Office, load_office
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.server import LockServer
from assistantx.sim.office import SimOffice
from assistantx.sim.session import SimSession

STAPLER_TO_LEE = [{"holds": ["lee", "stapler:zhang"]}, {"informed": "lee"}]


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def _fetch_stapler(s: SimSession) -> None:
    """Zhang's stapler to Lee: two hand-overs at the robot's locker."""
    # Zhang's own yes in his own chat: the consent guard lets his stapler's codes out then
    await s.do(Inquire(contact="zhang", question="Could you lend Lee your stapler?"))
    assert (await s.do(Wait(timeout_s=60))).ok
    await s.do(Move(place="zhang"))
    await s.do(SendQR(contact="zhang", item="stapler:zhang", purpose="deposit"))
    r = await s.do(WaitInPlace(person="zhang"))
    assert r.ok, r.observation
    await s.do(Move(place="lee"))
    await s.do(SendQR(contact="lee", item="stapler:zhang", purpose="collect"))
    r = await s.do(WaitInPlace(person="lee"))
    assert r.ok, r.observation
    await s.do(Inform(contact="lee", content="Zhang's stapler is in the locker for you."))


async def test_handover_follows_the_navigator_robot(office: Office) -> None:
    clock = SimClock()
    robot = NavigatorRobot.from_files(office, clock, localize=False)
    async with SimSession(office, requester="lee", robot=robot, clock=clock) as s:
        await _fetch_stapler(s)
        assert s.sim.check(STAPLER_TO_LEE) == [True, True]
        zhang, lee = office.person("zhang").location, office.person("lee").location
        assert s.sim.robot.state().place == lee == s.sim.robot.place
        # Distances are the planner's, not straight lines between desks.
        driven = robot.path_distance(office.robot.home, zhang) + robot.path_distance(zhang, lee)
        assert s.sim.robot.odometer_m == pytest.approx(driven, abs=2e-3)  # mm-rounded
        assert driven > office.distance(office.robot.home, zhang) + office.distance(zhang, lee)
        arrivals = [e.detail["place"] for e in s.sim.world.log if e.kind == "robot_arrived"]
        assert arrivals == [zhang, lee]


@pytest.fixture
async def lock_server() -> AsyncIterator[tuple[LockServer, LockKeys]]:
    keys = LockKeys.from_secret("a secret shared by the simulated lock and the assistant")
    server = LockServer(LockController("locker-t", keys.codes, WallClock()), keys.link_key)
    await server.start()
    try:
        yield server, keys
    finally:
        await server.stop()


async def test_handover_through_a_tcp_locker(
    office: Office, lock_server: tuple[LockServer, LockKeys]
) -> None:
    server, keys = lock_server
    host, port = server.address
    locker = TcpLocker(host, port, keys, lock_id="locker-t", render_png=False)
    # Real time (sped up) runs while the scan and the door close travel over TCP.
    clock = WallClock(speedup=200)
    async with SimSession(office, requester="lee", locker=locker, clock=clock) as s:
        await _fetch_stapler(s)
        assert s.sim.check(STAPLER_TO_LEE) == [True, True]
        assert s.stm.embodied.locker_contents == []
        status = await locker.status()
        assert status.door == "closed" and status.lock_id == "locker-t"


def test_a_locker_people_cannot_use_is_refused(office: Office) -> None:
    class Sealed(TcpLocker):
        simulate_scan = None  # type: ignore[assignment]

    keys = LockKeys.from_secret("x" * 32)
    with pytest.raises(TypeError, match="simulate_scan"):
        SimOffice(office, locker=Sealed("127.0.0.1", 1, keys))


async def test_after_the_end_nothing_arrives_about_the_instruction(office: Office) -> None:
    async with SimSession(office, requester="lee", instruction_id="ins-a") as s:
        await s.do(Move(place="wang"))
        await s.do(SendQR(contact="wang", item="stapler:wang", purpose="deposit"))
        await s.do(Inform(contact="wang", content="The robot is at your desk for your stapler."))
        await s.do(Inquire(contact="zhang", question="Do you have a stapler?"))
        s.sim.end_instruction("ins-a")
        received = len(s.sim.messenger.received)
        await s.sim.clock.sleep(600)  # zhang's answer and wang's walk to the robot were due
        assert len(s.sim.messenger.received) == received
        assert s.sim.codes == [] and not any(i == "ins-a" for i, _ in s.sim.told)
        assert s.sim.world.holder["stapler:wang"] == "wang"


async def test_before_the_end_the_reply_arrives(office: Office) -> None:
    async with SimSession(office, requester="lee", instruction_id="ins-b") as s:
        await s.do(Inquire(contact="zhang", question="Do you have a stapler?"))
        r = await s.do(Wait(timeout_s=60))
        assert r.ok and "stapler" in r.observation
