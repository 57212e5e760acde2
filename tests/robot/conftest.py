"""Shared robot fixtures: the office map, its anchors and one planner (built once per run)."""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.adapters.robot.nav.anchors import Anchor, load_anchors
from assistantx.adapters.robot.nav.costmap import Costmap
from assistantx.adapters.robot.nav.occupancy_map import OccupancyMap, load_map
from assistantx.adapters.robot.nav.planner import GridPlanner

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


def shared_map(name: str) -> Path:
    """A real map from ``shared/maps`` (next to the repository in CI; a worktree may sit
    deeper, so look upwards)."""
    for parent in REPO.parents:
        candidate = parent / "shared" / "maps" / f"{name}.yaml"
        if candidate.is_file():
            return candidate
    raise FileNotFoundError(f"shared/maps/{name}.yaml not found above {REPO}")
