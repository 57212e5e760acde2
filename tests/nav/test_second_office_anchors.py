"""The second office (dataset/offices/harbour) on the default floor plan: an anchor for every
location, at the office's coordinates, each reachable by the planner."""

from __future__ import annotations

import math
from pathlib import Path

import yaml

from assistantx.nav.anchors import load_anchors
from assistantx.nav.planner import GridPlanner

REPO = Path(__file__).resolve().parents[2]
HARBOUR = REPO / "dataset" / "offices" / "harbour"


def test_harbour_anchors_cover_its_locations_and_are_reachable(
    office_planner: GridPlanner,
) -> None:
    office = yaml.safe_load((HARBOUR / "office.yaml").read_text(encoding="utf-8"))
    anchors = load_anchors(HARBOUR / "office.anchors.yaml")
    locations = {loc["id"]: (loc["x"], loc["y"]) for loc in office["locations"]}
    assert set(anchors) == set(locations)
    for name, (x, y) in locations.items():
        assert (anchors[name].x, anchors[name].y) == (x, y)
    home = anchors[office["robot"]["home"]]
    paths = office_planner.plan_many((home.x, home.y), [(a.x, a.y) for a in anchors.values()])
    for name, path in zip(anchors, paths, strict=True):
        assert path is not None, f"{name} unreachable"
        a = anchors[name]
        assert path.length_m >= math.hypot(a.x - home.x, a.y - home.y) - 1e-9
