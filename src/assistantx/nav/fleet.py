"""A fleet dispatcher for several robot bases on one map (first cut; Open-RMF's task
allocation as the anchor): each trip goes to the robot that would finish it soonest, and
robots yield to each other through time-windowed reservations of map blocks.

- A ``Trip`` is one instruction's drive: its stops in order, released at ``release_s``, with
  ``dwell_s`` at each stop (a hand-over).
- ``Dispatcher.assign`` bids the trip to every robot: start when the robot is free (and the
  trip released), drive the planner's paths at ``speed_mps``, dwell at each stop; the lowest
  finish time wins (rmf_task's cost is the same quantity, the time the task would end).
- ``Reservations`` hold, per 0.5 m block of the map, the time windows in which a robot
  passes or dwells there (widened by ``margin_s``). The winner's start is delayed, second by
  second, until its whole timed path is free of other robots' windows: it yields by waiting
  where it is. Windows are only ever added in assignment order, so an earlier robot is never
  delayed by a later one and no cycle of waits (a deadlock) can form.

Not modelled yet: robots idle at a stop do not reserve it (stops are anchors beside desks,
off the aisles), and a driven robot that falls behind its timed path does not re-reserve.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from assistantx.nav.planner import GridPlanner, Path

Point = tuple[float, float]


@dataclass(frozen=True)
class Trip:
    id: str
    release_s: float
    stops: tuple[Point, ...]
    dwell_s: float = 20.0


@dataclass
class FleetRobot:
    name: str
    position: Point
    free_at_s: float = 0.0
    lease: int = 0  # a fencing token per robot: bumped on every trip it is given
    trips: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class Assignment:
    trip: str
    robot: str
    lease: int
    start_s: float
    first_stop_s: float  # when the robot reaches the trip's first stop
    finish_s: float
    yielded_s: float  # how long it waited for other robots' reservations


class Reservations:
    def __init__(self, block_m: float = 0.5, margin_s: float = 1.5) -> None:
        self.block_m = block_m
        self.margin_s = margin_s
        self._windows: dict[tuple[int, int], list[tuple[float, float, str]]] = {}

    def _blocks(self, xy: np.ndarray) -> list[tuple[int, int]]:
        cells = np.floor(xy / self.block_m).astype(np.int64)
        return [(int(x), int(y)) for x, y in cells]

    def free(
        self, timed: Sequence[tuple[np.ndarray, float, float]], robot: str, shift: float
    ) -> bool:
        for xy, t0, t1 in timed:
            for block in self._blocks(xy):
                for a, b, who in self._windows.get(block, ()):
                    if who != robot and t0 + shift < b and a < t1 + shift:
                        return False
        return True

    def reserve(
        self, timed: Sequence[tuple[np.ndarray, float, float]], robot: str, shift: float
    ) -> None:
        for xy, t0, t1 in timed:
            for block in set(self._blocks(xy)):
                self._windows.setdefault(block, []).append(
                    (t0 + shift - self.margin_s, t1 + shift + self.margin_s, robot)
                )


class Dispatcher:
    def __init__(
        self,
        planner: GridPlanner,
        robots: dict[str, Point],
        speed_mps: float = 0.5,
        reservations: Reservations | None = None,
    ) -> None:
        self.planner = planner
        self.robots = {name: FleetRobot(name, xy) for name, xy in robots.items()}
        self.speed_mps = speed_mps
        self.reservations = reservations or Reservations()
        self._paths: dict[tuple[Point, Point], Path] = {}

    def path(self, a: Point, b: Point) -> Path:
        if (a, b) not in self._paths:
            self._paths[(a, b)] = self.planner.plan(a, b)
        return self._paths[(a, b)]

    def _timed(
        self, start: Point, trip: Trip, t: float
    ) -> tuple[list[tuple[np.ndarray, float, float]], float, float]:
        """The trip's path pieces with their time windows from ``t``; first-stop and end times."""
        pieces: list[tuple[np.ndarray, float, float]] = []
        here = start
        first_stop = math.nan
        for stop in trip.stops:
            if stop != here:
                points = self.path(here, stop).resampled(self.block_m_half)
                steps = np.hypot(*np.diff(points, axis=0).T)
                times = t + np.r_[0.0, np.cumsum(steps)] / self.speed_mps
                for i in range(len(points)):
                    pieces.append((points[i : i + 1], float(times[i]), float(times[i])))
                t = float(times[-1])
            if math.isnan(first_stop):
                first_stop = t
            pieces.append((np.array([stop]), t, t + trip.dwell_s))
            t += trip.dwell_s
            here = stop
        return pieces, first_stop, t

    @property
    def block_m_half(self) -> float:
        return self.reservations.block_m / 2

    def assign(self, trip: Trip) -> Assignment:
        """Give ``trip`` to the robot that would finish it soonest, yielding to the others."""
        bids = []
        for robot in self.robots.values():
            start = max(robot.free_at_s, trip.release_s)
            _, _, finish = self._timed(robot.position, trip, start)
            bids.append((finish, robot.name))
        _, name = min(bids)
        robot = self.robots[name]
        start = max(robot.free_at_s, trip.release_s)
        timed, first_stop, finish = self._timed(robot.position, trip, start)
        shift = 0.0
        while not self.reservations.free(timed, name, shift):
            shift += 1.0
        self.reservations.reserve(timed, name, shift)
        robot.free_at_s = finish + shift
        robot.position = trip.stops[-1]
        robot.lease += 1
        robot.trips.append(trip.id)
        return Assignment(
            trip.id, name, robot.lease, start + shift, first_stop + shift, finish + shift, shift
        )


def serve(
    dispatcher: Dispatcher,
    trips: Sequence[Trip],
    on_assign: Callable[[Assignment], None] | None = None,
) -> list[Assignment]:
    """Assign every trip in release order."""
    done = []
    for trip in sorted(trips, key=lambda t: t.release_s):
        assignment = dispatcher.assign(trip)
        if on_assign is not None:
            on_assign(assignment)
        done.append(assignment)
    return done
