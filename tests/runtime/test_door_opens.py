"""A closed door on the way (maps/scenarios/office-meeting-door-opens.yaml: the meeting
room's only door is shut, and opened five minutes later): the requester is told in words
which door and that the robot comes back, and the robot gets in once it is open."""

from __future__ import annotations

from pathlib import Path

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.actions import Move
from assistantx.core.clock import SimClock
from assistantx.core.office import load_office
from assistantx.nav.anchors import load_anchors
from assistantx.nav.navigation import NavigationParams
from assistantx.nav.scenario import load_scenario, schedule_events
from assistantx.sim.session import SimSession

REPO = Path(__file__).resolve().parents[2]
SCENARIO = REPO / "maps" / "scenarios" / "office-meeting-door-opens.yaml"


async def test_the_robot_says_the_door_is_closed_and_comes_back_when_it_opens() -> None:
    scenario = load_scenario(SCENARIO)
    grid = scenario.load_map()
    world = scenario.world(grid)
    office = load_office()
    clock = SimClock()
    schedule_events(scenario, world, clock)
    robot = NavigatorRobot(
        office,
        grid,
        load_anchors(REPO / "maps" / "office.anchors.yaml"),
        clock,
        seed=scenario.seed,
        start="desk_08",
        world=world,
        # Plans here, not in the service's planning worker process (the default of a robot
        # that localizes): the same plans, without spawning a process that imports numpy and
        # scipy and measures the map's landmarks (about 3 CPU-s).
        params=NavigationParams(plan_in_process=False),
    )
    async with robot, SimSession(office, requester="lee", robot=robot, clock=clock) as session:
        result = await session.do(Move(place="meeting_room"))
        told = [t.text for t in session.stm.dialogue if t.direction == "out"]
    assert result.ok, result.observation
    assert robot.state().place == "meeting_room"
    assert clock.now() >= 300.0  # it got in only once the door had been opened
    assert told == [
        "The door on the way to Meeting room is closed. I'll come back when it's open: I try "
        "again every 3 minutes, for up to 15 minutes."
    ]
    assert robot.navigator.safety.collisions == 0
