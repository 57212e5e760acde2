"""Shared robot fixtures: the office map, its anchors and one planner (built once per run)."""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.robot.anchors import Anchor, load_anchors
from assistantx.robot.costmap import Costmap
from assistantx.robot.occupancy_map import OccupancyMap, load_map
from assistantx.robot.planner import GridPlanner

REPO = Path(__file__).resolve().parents[2]
FIXTURES = Path(__file__).parent / "fixtures"


@pytest.fixture(scope="session")
def office_map() -> OccupancyMap:
    return load_map(REPO / "maps" / "office.yaml")


@pytest.fixture(scope="session")
def office_anchors() -> dict[str, Anchor]:
    return load_anchors(REPO / "maps" / "office.anchors.yaml")


@pytest.fixture(scope="session")
def office_planner(office_map: OccupancyMap) -> GridPlanner:
    return GridPlanner(Costmap.inflate(office_map))
