"""NavigatorRobot: the in-process robot base on the simulated navigation stack.

``move_to(location_id)`` resolves the id to its map anchor, plans on the inflated costmap,
drives with pure pursuit while AMCL localizes from the simulated LiDAR, and checks arrival
against the true pose within ``arrival_tolerance_m``. The clock advances by the driving time
(a SimClock costs no real time; a WallClock lets the robot drive in real time).

``localize=False`` is the fast mode for the evaluation: the base traverses the planned path
kinematically (no LiDAR, no AMCL), taking path length / speed. Paths between anchors are
planned once per start anchor (one Dijkstra to every anchor) and cached, which also serves
``path_distance``.

Obstacles the map does not know can be dropped into the simulated world with ``block``, or a
whole simulated world (nav.ground_truth: moved furniture, closed doors, people walking) given
as ``world``. With AMCL on, a blocked way goes through nav2's recovery sequence (clear the
costmap, rotate, back up, wait) before the move fails with BlockedError, or DoorClosedError
when the only way runs through a shut doorway.

With AMCL on, planning and every chunk of driving (control, LiDAR, filter, obstacle layer,
costmap) run in a worker thread (``asyncio.to_thread``), and the search itself in a worker
process (scipy's Dijkstra holds the GIL), so the event loop keeps serving
requests while the robot drives; ``state()`` reads a snapshot the worker publishes after
each chunk, never arrays the worker is changing.

At construction every office location must have an anchor, and every anchor must stand in
free space the robot fits in and be reachable from the others; the first problem is raised
as one MapError line naming the anchors file, the location id and the problem.
"""

from __future__ import annotations

import asyncio
import functools
import logging
import math
from collections.abc import Iterator, Mapping
from functools import lru_cache
from pathlib import Path as FilePath
from weakref import WeakKeyDictionary

import numpy as np

from assistantx.core.clock import Clock
from assistantx.core.errors import (
    BlockedError,
    LocalizationLostError,
    MapError,
    RobotError,
    UnreachableError,
)
from assistantx.core.office import Office
from assistantx.core.ports.robot import MoveResult, Pose, RobotBase, RobotState
from assistantx.nav.anchor_check import AnchorProblem, check_anchors
from assistantx.nav.anchors import Anchor, load_anchors
from assistantx.nav.geometry import FloatArray
from assistantx.nav.ground_truth import GroundTruth
from assistantx.nav.navigation import NavigationParams, Navigator
from assistantx.nav.occupancy_map import OCCUPIED, OccupancyMap, load_map
from assistantx.nav.plan_process import PLAN_PROCESS
from assistantx.nav.planner import GridPlanner, Path
from assistantx.nav.traffic import Traffic

logger = logging.getLogger(__name__)

DEFAULT_MAP = FilePath(__file__).resolve().parents[2] / "data" / "maps" / "office.yaml"
MAX_PARTICLES_SHOWN = 500


# Anchor-to-anchor paths per planner (so per map), keyed by anchor coordinates: shared by
# every robot on the same map, so the evaluation's thousands of moves plan each pair once.
_PATH_TABLES: WeakKeyDictionary[
    GridPlanner, dict[tuple[tuple[float, float], tuple[float, float]], Path | None]
] = WeakKeyDictionary()


def _checked(planner: GridPlanner, anchors: Mapping[str, Anchor]) -> list[AnchorProblem]:
    """check_anchors, once per planner (so per map) and set of anchors."""
    key = tuple(sorted((k, a.x, a.y) for k, a in anchors.items()))
    per_map = _ANCHOR_CHECKS.setdefault(planner, {})
    if key not in per_map:
        per_map[key] = check_anchors(planner.costmap, anchors, planner.known_components())
    return per_map[key]


_ANCHOR_CHECKS: WeakKeyDictionary[
    GridPlanner, dict[tuple[tuple[str, float, float], ...], list[AnchorProblem]]
] = WeakKeyDictionary()


def _xy(anchor: Anchor) -> tuple[float, float]:
    return (anchor.x, anchor.y)


@lru_cache(maxsize=8)
def _load_cached(
    map_yaml: FilePath, anchors_yaml: FilePath, _stamp: tuple[int, int]
) -> tuple[OccupancyMap, dict[str, Anchor]]:
    return load_map(map_yaml), load_anchors(anchors_yaml)


class NavigatorRobot(RobotBase):
    def __init__(
        self,
        office: Office,
        grid: OccupancyMap,
        anchors: Mapping[str, Anchor],
        clock: Clock,
        seed: int = 0,
        *,
        localize: bool = True,
        start: str | None = None,
        params: NavigationParams | None = None,
        arrival_tolerance_m: float = 0.15,
        anchors_file: str | FilePath | None = None,
        world: GroundTruth | None = None,
        traffic: Traffic | None = None,
        name: str = "robot",
        search_off_loop: bool = False,
    ) -> None:
        """``traffic``: robots sharing this map (a fleet); this one, called ``name`` there,
        claims the floor it drives over and yields to the others (nav.traffic). None: alone
        on the floor, driving exactly as before. ``search_off_loop``: the kinematic base's
        path searches run in a worker thread (a service's loop keeps serving meanwhile);
        off where the loop keeps virtual time (``sim.virtual_time``), which jumps ahead
        while it waits for a thread."""
        super().__init__()
        where = f"{anchors_file}: " if anchors_file is not None else ""
        missing = sorted({loc.id for loc in office.locations} - anchors.keys())
        if missing:
            raise MapError(f"{where}no map anchor for location(s): {', '.join(missing)}")
        self.office = office
        self.anchors = dict(anchors)
        self.clock = clock
        self.localize = localize
        self.arrival_tolerance_m = arrival_tolerance_m
        self._place: str | None = start or office.robot.home
        if self._place not in self.anchors:
            raise MapError(f"start place {self._place!r} has no map anchor")
        home = self.anchors[self._place]
        self._grid = grid
        if localize and params is None:
            # Driving serves requests meanwhile: plans go to a worker process (see
            # plan_process), where scipy's search cannot hold this process's GIL.
            params = NavigationParams(plan_in_process=True)
        self._navigator = Navigator(
            grid,
            np.array([home.x, home.y, home.yaw]),
            np.random.default_rng(seed),
            params,
            localize=localize,
            world=world,
        )
        # The planner on the map alone; the navigator may swap in one that holds obstacles it
        # saw, which must not leak into the shared anchor path table.
        self._map_planner = self._navigator.map_planner
        used = {loc.id for loc in office.locations} | {self._place}
        problems = _checked(self._map_planner, {k: v for k, v in anchors.items() if k in used})
        if problems:
            first = problems[0]
            more = f" (and {len(problems) - 1} more)" if len(problems) > 1 else ""
            raise MapError(f"{where}anchor {first.anchor!r}: {first.problem}{more}")
        self._snapshot: RobotState | None = None
        self._paths = _PATH_TABLES.setdefault(self._map_planner, {})
        self._walks: dict[str, dict[str, float | None]] = {}
        self._obstacles: list[tuple[float, float, float]] = []
        self._goal: str | None = None
        self._path: Path | None = None
        self._lock = asyncio.Lock()
        self.traffic = traffic
        self.name = name
        self.search_off_loop = search_off_loop
        if traffic is not None:
            traffic.stand(name, home.x, home.y)

    @classmethod
    def from_files(
        cls,
        office: Office,
        clock: Clock,
        seed: int = 0,
        *,
        map_yaml: str | FilePath = DEFAULT_MAP,
        anchors_yaml: str | FilePath | None = None,
        localize: bool = True,
        start: str | None = None,
        traffic: Traffic | None = None,
        name: str = "robot",
        search_off_loop: bool = False,
        params: NavigationParams | None = None,
    ) -> NavigatorRobot:
        """``params``: as for the constructor (None: a localizing robot plans in the worker
        process, see plan_process)."""
        map_path = FilePath(map_yaml).resolve()
        anchors_path = FilePath(
            anchors_yaml or map_path.with_name(map_path.stem + ".anchors.yaml")
        ).resolve()
        # Cached per file version: every robot built from the same files shares one map
        # object, and with it the planner graph and the anchor path table.
        try:
            stamp = (map_path.stat().st_mtime_ns, anchors_path.stat().st_mtime_ns)
        except OSError as exc:
            raise MapError(f"cannot read map files: {exc}") from exc
        grid, anchors = _load_cached(map_path, anchors_path, stamp)
        return cls(
            office,
            grid,
            anchors,
            clock,
            seed,
            localize=localize,
            start=start,
            anchors_file=anchors_path,
            traffic=traffic,
            name=name,
            search_off_loop=search_off_loop,
            params=params,
        )

    async def _start(self) -> None:
        """Start the planning worker process before the first move (see plan_process)."""
        if self._navigator.params.plan_in_process:
            await asyncio.to_thread(PLAN_PROCESS.warm, self._navigator.planner)

    async def _stop(self) -> None:
        """Stop the planning worker with the robot: a stopped service leaves no process."""
        if self._navigator.params.plan_in_process:
            await asyncio.to_thread(PLAN_PROCESS.close)

    @property
    def grid(self) -> OccupancyMap:
        """The map the robot believes (without obstacles dropped into the world)."""
        return self._grid

    @property
    def navigator(self) -> Navigator:
        """The simulated navigation stack (for tests, benchmarks and the simulator)."""
        return self._navigator

    # -- RobotBase ---------------------------------------------------------------------------
    async def move_to(self, location_id: str) -> MoveResult:
        if location_id not in self.anchors:
            raise UnreachableError(f"{location_id!r} is not a place on the map")
        if self._lock.locked():
            raise RobotError(f"already driving to {self._goal}")
        async with self._lock:
            return await self._move(location_id)

    async def _move(self, location_id: str) -> MoveResult:
        nav = self._navigator
        anchor = self.anchors[location_id]
        started_at, odometer_before = nav.base.time_s, nav.base.odometer_m
        if not self.localize and (not self.search_off_loop or self._has_path_to(location_id)):
            path = self._plan(location_id)  # kinematic: a path at hand, or searched here
        else:
            # A search: the kinematic base's first table of paths from a place (a plan_many
            # to every anchor) held the service's loop for up to 1.2 s with 50 instructions
            # running (bench/service_load.py); the compiled search releases the GIL.
            path = await asyncio.to_thread(self._plan, location_id)
        if self.traffic is not None:
            path = await self._yield_to_others(location_id, path)
        self._goal, self._path, self._place = location_id, path, None
        logger.info("driving to %s (%.1f m)", location_id, path.length_m)
        if self.traffic is not None and not self.localize:
            chunks = self._follow_in_traffic(path, anchor.yaw)
        elif self.localize:
            chunks = nav.navigate(self._stop_point(anchor, path), anchor.yaw, path)
        else:
            chunks = nav.follow(path, anchor.yaw)
        try:
            while True:
                if self.localize:
                    seconds = await asyncio.to_thread(self._drive_chunk, chunks)
                else:
                    seconds = next(chunks, None)
                if seconds is None:
                    break
                await self.clock.sleep(seconds)
                if self.traffic is not None:
                    true = nav.base.true_pose
                    self.traffic.moved(self.name, float(true[0]), float(true[1]))
        except (RobotError, asyncio.CancelledError):
            # Stopped short (blocked, or the instruction was cancelled): no goal, and no
            # planned path left for the dashboard to draw.
            self._goal, self._path = None, None
            raise
        finally:
            self._snapshot = None
            if self.traffic is not None:  # standing again, wherever it stopped
                true = nav.base.true_pose
                self.traffic.stand(self.name, float(true[0]), float(true[1]))
        true = nav.base.true_pose
        stop_x, stop_y = self._stop_point(anchor, path)
        miss = math.hypot(true[0] - stop_x, true[1] - stop_y)
        self._goal, self._path = None, None
        if miss > self.arrival_tolerance_m:
            raise LocalizationLostError(
                f"believed to be at {location_id} but {miss:.2f} m away from it"
            )
        self._place = location_id
        return MoveResult(
            place=location_id,
            distance_m=round(nav.base.odometer_m - odometer_before, 3),
            duration_s=round(nav.base.time_s - started_at, 3),
        )

    async def _yield_to_others(self, location_id: str, path: Path) -> Path:
        """Wait where it stands until the floor the path sweeps is free of other robots,
        going round robots that stand in the way when the floor leaves room; returns the
        path to drive."""
        assert self.traffic is not None
        started = self.clock.timer()
        points = await self.traffic.claim(
            self.name, path.points, functools.partial(self._round_standing, location_id)
        )
        waited = self.clock.timer() - started
        if waited > 0:
            logger.info("%s yielded %.1f s to other robots", self.name, waited)
        if points is path.points:
            return path
        length = float(np.hypot(*np.diff(points, axis=0).T).sum())
        return Path(points, length, length, len(points))

    def _stop_point(self, anchor: Anchor, path: Path) -> tuple[float, float]:
        """Where the robot stops for ``anchor``: the anchor; among other robots, the end of
        its claimed path, which is beside the anchor when another robot stands on it."""
        if self.traffic is None:
            return (anchor.x, anchor.y)
        return (float(path.points[-1][0]), float(path.points[-1][1]))

    def _round_standing(
        self, location_id: str, robots: list[tuple[float, float]]
    ) -> FloatArray | None:
        """A path to ``location_id`` that keeps clear of the robots standing at ``robots``."""
        assert self.traffic is not None
        goal = self.anchors[location_id]
        nav = self._navigator
        radius = self.traffic.params.standing_radius_m
        res = self._grid.resolution
        rings = []
        for ox, oy in robots:
            xs, ys = np.meshgrid(
                np.arange(ox - radius, ox + radius + res, res),
                np.arange(oy - radius, oy + radius + res, res),
            )
            inside = np.hypot(xs - ox, ys - oy) <= radius
            rings.append(np.column_stack([xs[inside], ys[inside]]))
        costmap = nav.costmap.with_obstacles(np.concatenate(rings))
        planner = GridPlanner(costmap, nav.params.planner)
        start = (float(nav.pose[0]), float(nav.pose[1]))
        for stop in self._stops_beside(goal, robots, radius):
            if self.traffic.holders(self.traffic.blocks_along(np.array([stop])), self.name):
                continue  # too close to another robot's footprint
            try:
                around = planner.plan(start, stop)
            except RobotError:
                continue
            return around.points
        return None

    @staticmethod
    def _stops_beside(
        goal: Anchor, robots: list[tuple[float, float]], radius: float
    ) -> list[tuple[float, float]]:
        """The goal, or when another robot stands on it, points beside it nearest first (the
        robots then serve the same desk side by side: a person walks a step further)."""
        if not any(math.hypot(goal.x - x, goal.y - y) < radius for x, y in robots):
            return [(goal.x, goal.y)]
        beside = []
        for distance in (radius + 0.3, radius + 0.6, radius + 0.9):
            for k in range(12):
                angle = k * math.tau / 12
                beside.append(
                    (goal.x + distance * math.cos(angle), goal.y + distance * math.sin(angle))
                )
        return [
            p for p in beside if all(math.hypot(p[0] - x, p[1] - y) >= radius for x, y in robots)
        ]

    def _follow_in_traffic(self, path: Path, goal_yaw: float) -> Iterator[float]:
        """Kinematic mode among other robots: along the path step by step (not in one jump),
        so the floor behind is handed back as the robot passes it and others see it move."""
        assert self.traffic is not None
        base = self._navigator.base
        drive = self._navigator.params.drive
        x, y = float(base.true_pose[0]), float(base.true_pose[1])
        for x, y, seconds in self.traffic.drive(self.name, path.points, drive.max_speed_mps):
            step = math.hypot(x - base.true_pose[0], y - base.true_pose[1])
            heading = math.atan2(y - base.true_pose[1], x - base.true_pose[0])
            base.true_pose = np.array([x, y, heading])
            base.odom_pose = base.true_pose.copy()
            base.time_s += seconds
            base.odometer_m += step
            yield seconds
        turn = abs(math.remainder(goal_yaw - float(base.true_pose[2]), math.tau))
        base.true_pose = np.array([x, y, goal_yaw])
        base.odom_pose = base.true_pose.copy()
        base.time_s += turn / drive.max_turn_rate_rps
        yield turn / drive.max_turn_rate_rps

    def _drive_chunk(self, chunks: Iterator[float]) -> float | None:
        """In the worker thread: drive one chunk, then publish what state() shows."""
        seconds = next(chunks, None)
        self._snapshot = self._live_state()
        return seconds

    def state(self) -> RobotState:
        snapshot = self._snapshot
        if snapshot is not None:  # a worker is driving: read what it published
            return snapshot
        return self._live_state()

    def _live_state(self) -> RobotState:
        nav = self._navigator
        believed = nav.pose
        particles = None
        if nav.filter is not None:
            sample = nav.filter.sample(MAX_PARTICLES_SHOWN)
            particles = [(float(x), float(y), float(t)) for x, y, t in sample]
        path = self._path.points if self._path is not None else np.zeros((0, 2))
        return RobotState(
            place=self._place,
            pose=Pose(x=float(believed[0]), y=float(believed[1]), yaw=float(believed[2])),
            moving=self._goal is not None,
            goal=self._goal,
            path=[(float(x), float(y)) for x, y in path],
            particles=particles,
            odometer_m=nav.base.odometer_m,
        )

    # -- planning ----------------------------------------------------------------------------
    def path_distance(self, a: str, b: str) -> float:
        """Metres along the planned path between the anchors of two locations (cached)."""
        for location_id in (a, b):
            if location_id not in self.anchors:
                raise UnreachableError(f"{location_id!r} is not a place on the map")
        path = self._anchor_path(a, b)
        if path is None:
            self._explain_unreachable(a, b)
        assert path is not None
        return path.length_m

    def path_length(self, a: str, b: str) -> float:
        """Metres along the map planner's path from a's anchor to b's, for the walking
        estimate. Each start is planned on its own (one Dijkstra per start, cached): smoothed
        grid paths are not symmetric, and reusing reversed paths in whatever order the robot
        happened to drive would make the same walk measure differently from one day to the
        next."""
        for place in (a, b):
            if place not in self.anchors:
                raise UnreachableError(f"{place!r} is not a place on the map")
        if a not in self._walks:
            names = list(self.anchors)
            paths = self._map_planner.plan_many(
                _xy(self.anchors[a]), [_xy(self.anchors[n]) for n in names]
            )
            self._walks[a] = {
                n: None if p is None else p.length_m for n, p in zip(names, paths, strict=True)
            }
        length = self._walks[a][b]
        if length is None:
            raise UnreachableError(f"no path from {a} to {b}")
        return length

    def _explain_unreachable(self, a: str, b: str) -> None:
        """Re-plan the one pair to raise UnreachableError with the planner's reason."""
        start, goal = self.anchors[a], self.anchors[b]
        self._map_planner.plan((start.x, start.y), (goal.x, goal.y))
        raise UnreachableError(f"no path from {a} to {b}")

    def _anchor_path(self, a: str, b: str) -> Path | None:
        start, goal = _xy(self.anchors[a]), _xy(self.anchors[b])
        if (start, goal) not in self._paths:
            ends = [_xy(anchor) for anchor in self.anchors.values()]
            paths = self._map_planner.plan_many(start, ends)
            for end, path in zip(ends, paths, strict=True):
                self._paths[(start, end)] = path
                if path is not None and (end, start) not in self._paths:
                    reverse = Path(
                        path.points[::-1].copy(), path.length_m, path.cost, path.grid_cells
                    )
                    self._paths[(end, start)] = reverse
        return self._paths[(start, goal)]

    def _has_path_to(self, location_id: str) -> bool:
        """Whether the kinematic base's path there is in the table already (no search)."""
        if self._place is None or self._obstacles:
            return False
        return (_xy(self.anchors[self._place]), _xy(self.anchors[location_id])) in self._paths

    def plan_to(self, location_id: str) -> Path:
        """The path the robot would take from where it is to ``location_id``."""
        if location_id not in self.anchors:
            raise UnreachableError(f"{location_id!r} is not a place on the map")
        return self._plan(location_id)

    def _plan(self, location_id: str) -> Path:
        anchor = self.anchors[location_id]
        nav = self._navigator
        if not self.localize and self._place is not None and not self._obstacles:
            cached = self._anchor_path(self._place, location_id)
            if cached is None:
                self._explain_unreachable(self._place, location_id)
            assert cached is not None
            return cached
        path = nav.plan((anchor.x, anchor.y))
        if not self.localize and self._obstacles and self._crosses_obstacle(path):
            # The kinematic base has no LiDAR: it "sees" the world's obstacles by replanning
            # on a costmap that holds them, and is blocked if there is no way round.
            try:
                path = GridPlanner(
                    nav.costmap.with_obstacles(self._obstacle_points()), nav.params.planner
                ).plan((float(nav.pose[0]), float(nav.pose[1])), (anchor.x, anchor.y))
            except UnreachableError as exc:
                raise BlockedError(f"the way to {location_id} is blocked: {exc}") from exc
        return path

    # -- the simulated world -----------------------------------------------------------------
    def block(self, x: float, y: float, radius_m: float) -> None:
        """Drop a round obstacle (unknown to the map) into the simulated world."""
        self._obstacles.append((x, y, radius_m))
        data = self._grid.data.copy()
        ix, iy = np.meshgrid(np.arange(self._grid.width), np.arange(self._grid.height))
        cx, cy = self._grid.cell_to_world(ix, iy)
        for ox, oy, r in self._obstacles:
            data[np.hypot(cx - ox, cy - oy) <= r] = OCCUPIED
        self._navigator.set_world(self._grid.with_data(data))

    def forget_obstacles(self) -> None:
        """Forget what the robot saw (the world stays as it is)."""
        self._navigator.reset_obstacles()

    def clear_obstacles(self) -> None:
        """Remove the dropped obstacles from the world and from what the robot remembers."""
        self._obstacles.clear()
        self._navigator.set_world(self._grid)
        self._navigator.reset_obstacles()

    def _obstacle_points(self) -> FloatArray:
        points = []
        res = self._grid.resolution
        for ox, oy, r in self._obstacles:
            xs, ys = np.meshgrid(
                np.arange(ox - r, ox + r + res, res), np.arange(oy - r, oy + r + res, res)
            )
            inside = np.hypot(xs - ox, ys - oy) <= r
            points.append(np.column_stack([xs[inside], ys[inside]]))
        return np.concatenate(points)

    def _crosses_obstacle(self, path: Path) -> bool:
        dense = path.resampled(self._grid.resolution)
        clearance = self._navigator.params.inflation.robot_radius
        return any(
            bool((np.hypot(dense[:, 0] - ox, dense[:, 1] - oy) <= r + clearance).any())
            for ox, oy, r in self._obstacles
        )
