"""The navigator adapter drives on the office map (fixtures shared with tests/nav)."""

from helpers.maps import office_anchors, office_map, office_planner

__all__ = ["office_anchors", "office_map", "office_planner"]
