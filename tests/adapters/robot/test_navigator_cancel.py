"""A drive cut short by a cancelled instruction leaves no goal and no planned path behind (the
dashboard draws ``state().path``; an old path would stay on the map)."""

from __future__ import annotations

import asyncio
import contextlib

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.clock import SimClock
from assistantx.core.office import DEFAULT_OFFICE, load_office
from assistantx.nav.anchors import Anchor
from assistantx.nav.occupancy_map import OccupancyMap
from helpers.eventually import eventually


async def test_a_cancelled_drive_clears_its_path(
    office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    office = load_office(DEFAULT_OFFICE)
    robot = NavigatorRobot(
        office, office_map, office_anchors, SimClock(), seed=4, localize=False, start="desk_01"
    )
    async with robot:
        drive = asyncio.create_task(robot.move_to("desk_10"))
        # Each loop tick: the simulated drive can end within a few.
        await eventually(lambda: robot.state().path, what="the drive's path", interval_s=0)
        assert robot.state().moving and robot.state().path
        drive.cancel()
        with contextlib.suppress(asyncio.CancelledError):
            await drive
        state = robot.state()
        assert not state.moving
        assert state.path == []
        assert state.place is None  # stopped between places
        # And it can drive again afterwards.
        assert (await robot.move_to("desk_02")).place == "desk_02"
        assert robot.state().path == []
