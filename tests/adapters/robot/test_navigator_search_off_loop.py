"""The kinematic robot's first table of paths from a place is searched off the event loop: a
search of every anchor held the service's loop for up to a second (bench/service_load.py), so
other instructions and HTTP requests waited on it."""

from __future__ import annotations

import asyncio
import threading
from typing import Any

import pytest

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.clock import SimClock
from assistantx.core.office import DEFAULT_OFFICE, load_office
from assistantx.nav.anchors import Anchor
from assistantx.nav.occupancy_map import OccupancyMap


async def test_the_loop_runs_while_the_first_paths_are_searched(
    office_map: OccupancyMap, office_anchors: dict[str, Anchor], monkeypatch: pytest.MonkeyPatch
) -> None:
    robot = NavigatorRobot(
        load_office(DEFAULT_OFFICE),
        office_map,
        office_anchors,
        SimClock(),
        seed=4,
        localize=False,
        start="desk_01",
        search_off_loop=True,  # as the service builds it
    )
    # As in a fresh service: no table searched yet (other tests share the module's tables).
    monkeypatch.setattr(robot, "_paths", {})
    planner = robot._map_planner
    search = planner.plan_many
    other_task_ran = threading.Event()
    searched_in: list[threading.Thread] = []

    def search_once_the_loop_moved_on(*args: Any, **kwargs: Any) -> Any:
        searched_in.append(threading.current_thread())
        # On the loop this would wait for a task that cannot run: the guard ends it.
        assert other_task_ran.wait(timeout=10), "the search held the loop"
        return search(*args, **kwargs)

    monkeypatch.setattr(planner, "plan_many", search_once_the_loop_moved_on)
    async with robot:
        drive = asyncio.create_task(robot.move_to("desk_10"))
        await asyncio.sleep(0)  # the drive starts: its first search, a table from desk_01
        other_task_ran.set()
        assert (await drive).place == "desk_10"
        assert searched_in and threading.main_thread() not in searched_in
        # The table is kept: the way back is at hand, no second search.
        searched_in.clear()
        assert (await robot.move_to("desk_01")).place == "desk_01"
        assert searched_in == []
