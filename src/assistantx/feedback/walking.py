"""Walking saved: what the requester would have walked to do an instruction themselves.

Computed, not asked. The requester's errand is the robot's errand seen from their desk: from
their desk to every place the robot went to for the instruction (people's desks and
facilities, in the order the robot first reached them), and back to their desk. Each leg is
measured with ``distance(a, b)``: along the robot base's floor map (``over_map``: the robot
port's ``path_length``) where the base has one, else the office's straight-line
``Office.distance`` (and the figure says which it used). The robot's distance is what it
actually drove for the instruction, summed from its move results.

Only an instruction that ended ``done`` saved walking: a failed or unachievable one saved the
requester nothing they could count on, so its ``saved_m`` is 0 (its walk is still recorded).
"""

from __future__ import annotations

import itertools
import logging
from collections.abc import Callable
from typing import Literal

from pydantic import BaseModel, Field

from assistantx.core.actions import Move
from assistantx.core.errors import RobotError, UnreachableError
from assistantx.core.office import Office
from assistantx.core.ports.robot import RobotBase
from assistantx.core.trace import Trace

logger = logging.getLogger(__name__)

DistanceFn = Callable[[str, str], float]
DistanceMethod = Literal["map", "straight-line"]


def over_map(robot: RobotBase) -> DistanceFn:
    """``distance(a, b)`` along the robot base's floor map (its ``path_length``); a base
    without a map raises UnreachableError, so ``estimate_walking`` measures straight lines
    and says so."""

    def distance(a: str, b: str) -> float:
        length = robot.path_length(a, b)
        if length is None:
            raise UnreachableError("the robot base has no floor map")
        return length

    return distance


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
