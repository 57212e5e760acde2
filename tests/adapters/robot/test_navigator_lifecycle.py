"""The navigator robot starts and stops cleanly, twice in a row, and drives after a restart."""

from __future__ import annotations

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.clock import SimClock
from assistantx.core.office import DEFAULT_OFFICE, load_office
from assistantx.nav.anchors import Anchor
from assistantx.nav.occupancy_map import OccupancyMap


async def test_navigator_starts_and_stops_twice(
    office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    office = load_office(DEFAULT_OFFICE)
    robot = NavigatorRobot(office, office_map, office_anchors, SimClock(), localize=False)
    home = robot.state().place
    destination = next(loc.id for loc in office.locations if loc.id != home)
    for place in (destination, home):
        await robot.start()
        await robot.start()
        assert robot.started and not robot.tasks
        assert place is not None and (await robot.move_to(place)).place == place
        await robot.stop()
        await robot.stop()
        assert not robot.started
