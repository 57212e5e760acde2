"""The navigation library's fixtures: the office map, its anchors and one planner."""

from __future__ import annotations

from pathlib import Path

from helpers.maps import REPO, office_anchors, office_map, office_planner

FIXTURES = Path(__file__).parent / "fixtures"

__all__ = ["FIXTURES", "REPO", "office_anchors", "office_map", "office_planner"]
