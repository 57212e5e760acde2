"""Walking saved: what the requester would have walked to do an instruction themselves.

Computed, not asked. The requester's errand is the robot's errand seen from their desk: from
their desk to every place the robot went to for the instruction (people's desks and
facilities, in the order the robot first reached them), and back to their desk. Each leg is
measured with ``distance(a, b)``: over the map's planner (``PlannedDistance``) where the
map is known, else the office's straight-line ``Office.distance`` (and the figure
says which it used). The robot's distance is what it actually drove for the instruction,
summed from its move results.

Only an instruction that ended ``done`` saved walking: a failed or unachievable one saved the
requester nothing they could count on, so its ``saved_m`` is 0 (its walk is still recorded).
"""

from __future__ import annotations

import itertools
import logging
from collections.abc import Callable, Mapping
from typing import Literal

from pydantic import BaseModel, Field

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.actions import Move
from assistantx.core.errors import RobotError, UnreachableError
from assistantx.core.office import Office
from assistantx.core.trace import Trace
from assistantx.nav.anchors import Anchor
from assistantx.nav.planner import GridPlanner

logger = logging.getLogger(__name__)

DistanceFn = Callable[[str, str], float]
DistanceMethod = Literal["map", "straight-line"]


class PlannedDistance:
    """``distance(a, b)``: metres along the map planner's path from a's anchor to b's.

    Each leg is planned from its own start (one Dijkstra per start, cached): smoothed grid
    paths are not symmetric, and a cache filled in whatever order the robot happened to drive
    would make the same walk measure differently from one day to the next.
    """

    def __init__(self, planner: GridPlanner, anchors: Mapping[str, Anchor]) -> None:
        self._planner = planner
        self._anchors = dict(anchors)
        self._from: dict[str, dict[str, float | None]] = {}

    @classmethod
    def of_robot(cls, robot: NavigatorRobot) -> PlannedDistance:
        return cls(robot.navigator.planner, robot.anchors)

    def __call__(self, a: str, b: str) -> float:
        for place in (a, b):
            if place not in self._anchors:
                raise UnreachableError(f"{place!r} is not a place on the map")
        if a not in self._from:
            start = self._anchors[a]
            names = list(self._anchors)
            paths = self._planner.plan_many(
                (start.x, start.y), [(self._anchors[n].x, self._anchors[n].y) for n in names]
            )
            self._from[a] = {
                n: None if p is None else p.length_m for n, p in zip(names, paths, strict=True)
            }
        length = self._from[a][b]
        if length is None:
            raise UnreachableError(f"no path from {a} to {b}")
        return length


class WalkingEstimate(BaseModel):
    instruction_id: str
    requester: str
    route: list[str] = Field(description="location ids: desk → places involved → desk")
    walk_m: float = Field(description="metres the requester would have walked")
    robot_m: float = Field(description="metres the robot drove for the instruction")
    saved_m: float = Field(description="walk_m when the instruction was done, else 0")
    method: DistanceMethod


def places_visited(trace: Trace) -> list[str]:
    """The location ids the robot reached for the instruction, each once, in order."""
    places: list[str] = []
    for result in trace.actions():
        if isinstance(result.action, Move) and result.ok and not result.refused:
            if result.action.place not in places:
                places.append(result.action.place)
    return places


def robot_distance(trace: Trace) -> float:
    """Metres driven, from the move results (what the odometer counted per move)."""
    total = 0.0
    for result in trace.actions():
        if isinstance(result.action, Move) and not result.refused:
            total += float(result.data.get("distance_m", 0.0) or 0.0)
    return total


def walking_route(office: Office, trace: Trace) -> list[str]:
    desk = office.person(trace.requester).location
    stops = [p for p in places_visited(trace) if p != desk]
    return [desk, *stops, desk] if stops else [desk]


def route_length(route: list[str], distance: DistanceFn) -> float:
    return sum(distance(a, b) for a, b in itertools.pairwise(route) if a != b)


def estimate_walking(
    office: Office,
    trace: Trace,
    distance: DistanceFn | None = None,
) -> WalkingEstimate:
    """The walk the requester was spared, over the map where ``distance`` is given."""
    route = walking_route(office, trace)
    method: DistanceMethod = "map" if distance is not None else "straight-line"
    try:
        walk = route_length(route, distance or office.distance)
    except RobotError as exc:
        # A place the planner cannot reach (a map older than the office file): measure the
        # straight line rather than lose the figure, and say so.
        logger.warning("walking for %s measured in straight lines: %s", trace.instruction_id, exc)
        walk, method = route_length(route, office.distance), "straight-line"
    return WalkingEstimate(
        instruction_id=trace.instruction_id,
        requester=trace.requester,
        route=route,
        walk_m=round(walk, 3),
        robot_m=round(robot_distance(trace), 3),
        saved_m=round(walk, 3) if trace.outcome == "done" else 0.0,
        method=method,
    )
