"""The maps tests drive on: the office's own and the three real nav2 maps committed in
``maps/nav2/`` (so a plain clone needs nothing outside the repository)."""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.nav.anchors import Anchor, load_anchors
from assistantx.nav.costmap import Costmap
from assistantx.nav.occupancy_map import OccupancyMap, load_map
from assistantx.nav.planner import GridPlanner

REPO = Path(__file__).resolve().parents[2]


def real_map(name: str) -> Path:
    """A real ROS map from ``maps/nav2`` (depot, warehouse, tb3_sandbox)."""
    path = REPO / "maps" / "nav2" / f"{name}.yaml"
    if not path.is_file():
        raise FileNotFoundError(f"maps/nav2/{name}.yaml is not in the repository")
    return path


@pytest.fixture(scope="session")
def office_map() -> OccupancyMap:
    return load_map(REPO / "maps" / "office.yaml")


@pytest.fixture(scope="session")
def office_anchors() -> dict[str, Anchor]:
    return load_anchors(REPO / "maps" / "office.anchors.yaml")


@pytest.fixture(scope="session")
def office_planner(office_map: OccupancyMap) -> GridPlanner:
    return GridPlanner(Costmap.inflate(office_map))
