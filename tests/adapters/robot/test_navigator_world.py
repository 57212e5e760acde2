"""NavigatorRobot in a simulated world apart from its map (issue 29): the meeting room's
door is shut in the world, not on the map; the robot tries its recoveries, then says it is
a door, and the rest of the office stays reachable."""

from __future__ import annotations

import pytest

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.clock import SimClock
from assistantx.core.errors import DoorClosedError
from assistantx.core.office import DEFAULT_OFFICE, load_office
from assistantx.nav.anchors import Anchor
from assistantx.nav.ground_truth import Door, GroundTruth
from assistantx.nav.occupancy_map import OccupancyMap


@pytest.mark.slow
async def test_a_shut_door_fails_the_move_as_a_closed_door(
    office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    office = load_office(DEFAULT_OFFICE)
    world = GroundTruth(office_map, doors=[Door((35.5, 8.95), (35.5, 10.65))])
    clock = SimClock()
    robot = NavigatorRobot(
        office, office_map, office_anchors, clock, seed=2, start="desk_08", world=world
    )
    async with robot:
        with pytest.raises(DoorClosedError, match=r"blocked: the doorway at \(35\.\d"):
            await robot.move_to("meeting_room")
        assert robot.navigator.recoveries == ["clear the costmap", "rotate", "back up", "wait"]
        assert robot.state().place is None and not robot.state().moving
        assert (await robot.move_to("desk_16")).place == "desk_16"
    assert robot.navigator.safety.collisions == 0
