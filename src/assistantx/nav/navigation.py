"""Navigation: plan on the costmap, follow the path with the simulated base, localize with AMCL.

``Navigator`` owns one simulated world (the truth the LiDAR sees, which may hold obstacles
the map does not), the map the robot believes, its costmap and planner, the simulated base
and the particle filter. ``follow`` is a generator that drives one path and yields the
simulated seconds that passed, so a caller can let a clock run alongside (and an asyncio
caller can await between chunks). It raises:

- BlockedError when the obstacle layer holds an obstacle on the path ahead and there is no
  way round it (the layer marks what the LiDAR sees that the map lacks and clears it again
  by ray tracing and decay; see obstacle_layer.py);
- LocalizationLostError when the scan stops matching the map at the estimated pose for
  several updates in a row (fewer than ``lost_match_ratio`` of the beams end near a wall or,
  up to ``lost_short_allowance``, short of one: on something the map lacks);
- BlockedError as well when the drive takes far longer than the path length warrants.

``navigate`` wraps plan and follow in nav2's recovery sequence: when the way is blocked it
clears the costmap, rotates on the spot (a fresh look all round), backs up, and waits, each
followed by a new plan, before it gives up; a goal the map itself cannot reach fails at once
(UnreachableError). Giving up, it says DoorClosedError when the map's way runs through a
doorway (a short gap in the walls) that the seen obstacles now shut.

With a simulated ``world`` (ground_truth.GroundTruth: the map plus what changed, and
people walking) the LiDAR sees the world, not the map; people move every control tick; a
collision monitor on the robot's own short-range scan stops the translation before it
touches anything (safety.py); and ``safety`` records collisions and near misses against the
truth. The robot's plans and its filter still read only its map and its scans.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from weakref import WeakKeyDictionary

import numpy as np

from assistantx.core.errors import (
    BlockedError,
    DoorClosedError,
    LocalizationLostError,
    UnreachableError,
)
from assistantx.nav.amcl import AmclParams, ParticleFilter
from assistantx.nav.costmap import (
    INSCRIBED,
    Costmap,
    InflationParams,
    update_obstacles,
)
from assistantx.nav.diff_drive import DriveParams, PurePursuit, SimulatedBase
from assistantx.nav.geometry import FloatArray, angle_diff
from assistantx.nav.ground_truth import GroundTruth
from assistantx.nav.lidar import LaserScan, Lidar, LidarParams, cast_rays
from assistantx.nav.motion_model import OdometryNoise
from assistantx.nav.obstacle_layer import ObstacleLayer, ObstacleLayerParams
from assistantx.nav.occupancy_map import OccupancyMap
from assistantx.nav.plan_process import PLAN_PROCESS
from assistantx.nav.planner import GridPlanner, Path, PlannerParams, StartInObstacleError
from assistantx.nav.safety import MonitorParams, SafetyRecord, translation_blocked

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class NavigationParams:
    # Beam skipping on: the robot drives among people and things its map lacks; the grey rim
    # of the known floor counts as a wall, as it is one in the world; and sigma_hit 0.1 m
    # (nav2's default is 0.2) for a LiDAR with 1 cm noise on a 5 cm map: on the scenarios'
    # routes it took the p95 error from 7-15 cm to 5-10 cm (warehouse, office, depot).
    amcl: AmclParams = field(
        default_factory=lambda: AmclParams(
            do_beamskip=True, unknown_rim_is_wall=True, sigma_hit=0.1
        )
    )
    inflation: InflationParams = field(default_factory=InflationParams)
    planner: PlannerParams = field(default_factory=PlannerParams)
    drive: DriveParams = field(default_factory=DriveParams)
    lidar: LidarParams = field(default_factory=LidarParams)
    obstacles: ObstacleLayerParams = field(default_factory=ObstacleLayerParams)
    odometry_noise: OdometryNoise = field(
        default_factory=lambda: OdometryNoise(0.005, 0.005, 0.005, 0.005)
    )
    lost_match_ratio: float = 0.5  # share of beams that must end within 0.3 m of a wall
    # ... or, up to this share of the beams, end short of the map's wall on their line (the
    # beam model's short readings: a person, a box, chairs the map lacks stand in front of
    # it). In a doorway stacked with boxes, half the beams can end on them while the
    # estimate is right; a cap keeps a scan made almost all of short readings (the robot
    # carried into a small room) from passing as a match.
    lost_short_allowance: float = 0.3
    lost_after_updates: int = 5
    block_lookahead_m: float = 1.5
    timeout_factor: float = 4.0  # give up after this multiple of the nominal driving time
    yield_every_s: float = 1.0
    # Plan in a worker process (plan_process): a search on a big map then never holds the
    # GIL of the process that serves requests. The service's robot turns it on.
    plan_in_process: bool = False
    monitor: MonitorParams = field(default_factory=MonitorParams)
    monitor_patience_s: float = 1.5  # held this long by the monitor: look again and replan
    recovery_wait_s: float = 5.0
    backup_m: float = 0.3
    backup_speed_mps: float = 0.15
    # A blocked point is a doorway when the map there is at most 2 x this wide across its
    # narrowest direction and, ``doorway_depth_m`` to one side of that gap, wider by
    # ``doorway_opening_m`` (a short gap in a wall, not a long corridor).
    doorway_half_width_m: float = 1.3
    doorway_depth_m: float = 0.6
    doorway_opening_m: float = 0.3


RECOVERIES = ("clear the costmap", "rotate", "back up", "wait")


@dataclass
class TrackingSample:
    time_s: float
    true_pose: FloatArray
    estimate: FloatArray


_PLANNERS: WeakKeyDictionary[
    OccupancyMap, dict[tuple[InflationParams, PlannerParams], GridPlanner]
] = WeakKeyDictionary()


def shared_planner(
    grid: OccupancyMap, inflation: InflationParams, params: PlannerParams
) -> GridPlanner:
    """One costmap and planner graph per map and parameters, shared by every Navigator on
    that map (building them takes ~0.3 s; the evaluation creates a robot per task)."""
    per_map = _PLANNERS.setdefault(grid, {})
    key = (inflation, params)
    if key not in per_map:
        per_map[key] = GridPlanner(Costmap.inflate(grid, inflation), params)
    return per_map[key]


class Navigator:
    def __init__(
        self,
        grid: OccupancyMap,
        start_pose: FloatArray,
        rng: np.random.Generator,
        params: NavigationParams | None = None,
        *,
        localize: bool = True,
        world: GroundTruth | None = None,
    ) -> None:
        self.params = params or NavigationParams()
        if world is not None and not localize:
            raise ValueError("a simulated world needs the sensing robot (localize=True)")
        self.world = world
        self.safety = SafetyRecord(self.params.monitor.near_miss_m)
        self.unmapped_shares: list[float] = []  # per filter update, with a world
        self.recoveries: list[str] = []  # recovery behaviours run, in order
        self.grid = grid
        self.rng = rng
        self.localize = localize
        # The map's costmap and planner, shared by every robot on this map, and this robot's
        # own layered copies, made when the obstacle layer first marks a cell.
        self.map_planner = shared_planner(grid, self.params.inflation, self.params.planner)
        self.planner = self.map_planner
        self.costmap = self.map_planner.costmap
        self.obstacles = ObstacleLayer(
            grid, self.costmap.obstacle_distance_m, self.params.obstacles
        )
        self.base = SimulatedBase(
            np.asarray(start_pose, dtype=float), rng, self.params.odometry_noise
        )
        self.lidar = Lidar(grid, self.params.lidar)
        self._map_blocked = grid.obstacles | grid.unknown_rim  # what the map holds
        if world is not None:
            self.lidar.see(world.blocked)
        self.filter: ParticleFilter | None = None
        if localize:
            self.filter = ParticleFilter(grid, self.params.amcl, rng)
            # The base starts docked at a known place: a tight initial cloud (10 cm, 1.8 deg).
            self.filter.initialize(self.base.true_pose, (0.01, 0.01, 0.001))
            self.filter.update(self.base.odom_pose, self.lidar.scan(self.base.true_pose, rng))
        self.tracking: list[TrackingSample] = []
        self._bad_matches = 0

    # -- what the robot believes -------------------------------------------------------------
    @property
    def pose(self) -> FloatArray:
        """The believed pose: the AMCL estimate carried forward by odometry (true pose in
        kinematic mode)."""
        if self.filter is None:
            return self.base.true_pose.copy()
        return self.filter.pose_from_odometry(self.base.odom_pose)

    def plan(self, goal: tuple[float, float]) -> Path:
        """Plan from the believed pose. Before planning the robot looks round once (a scan
        clears marks of obstacles that have gone) and old marks expire. A goal or a way that
        only the seen obstacles block raises BlockedError, which names them, not the map."""
        pose = self.pose
        start = (float(pose[0]), float(pose[1]))
        if self.filter is not None:
            self._sense_obstacles(self.lidar.scan(self.base.true_pose, self.rng))
        self._apply_obstacles(self.obstacles.expire(self.base.time_s))
        try:
            try:
                return self._plan_on(self.planner, start, goal)
            except UnreachableError as exc:
                if self.planner is self.map_planner:
                    raise
                self._plan_on(self.map_planner, start, goal)  # raises if the map is the reason
                raise BlockedError(
                    f"obstacles the robot sees block the way to ({goal[0]:.2f}, {goal[1]:.2f})"
                ) from exc
        except StartInObstacleError as exc:
            if self.filter is None:
                raise
            # A robot cannot stand inside a wall of the map: the estimate is what is wrong
            raise LocalizationLostError(
                f"the estimated pose ({start[0]:.2f}, {start[1]:.2f}) is inside a wall of the map"
            ) from exc

    def _plan_on(
        self, planner: GridPlanner, start: tuple[float, float], goal: tuple[float, float]
    ) -> Path:
        if self.params.plan_in_process:
            return PLAN_PROCESS.plan(planner, start, goal)
        return planner.plan(start, goal)

    def reset_obstacles(self) -> None:
        """Forget every mark (the map planner plans again)."""
        self.obstacles.clear()
        self.planner = self.map_planner
        self.costmap = self.map_planner.costmap

    def _sense_obstacles(self, scan: LaserScan) -> None:
        self._apply_obstacles(self.obstacles.update(self.pose, scan, self.base.time_s))

    def _apply_obstacles(self, changed: np.ndarray) -> None:
        if changed.size == 0:
            return
        if self.planner is self.map_planner:
            static = self.map_planner.costmap
            self.costmap = Costmap(
                static.grid, static.costs.copy(), static.obstacle_distance_m, static.params
            )
            self.planner = self.map_planner.layered(self.costmap)
        window = update_obstacles(
            self.map_planner.costmap, self.costmap, self.obstacles.marked, changed
        )
        if window is not None:
            self.planner.update_window(window)

    def set_world(self, world: OccupancyMap) -> None:
        """Change the truth the LiDAR sees (obstacles the map does not know)."""
        self.lidar.set_world(world)

    # -- driving ---------------------------------------------------------------------------
    def follow(self, path: Path, goal_yaw: float | None) -> Iterator[float]:
        """Drive along ``path``; yield simulated seconds as they pass."""
        p = self.params
        if self.filter is None:
            yield from self._traverse(path, goal_yaw)
            return
        controller = PurePursuit(path.resampled(0.05), goal_yaw, p.drive)
        nominal = path.length_m / p.drive.max_speed_mps + 2 * math.pi / p.drive.max_turn_rate_rps
        deadline = self.base.time_s + p.timeout_factor * nominal + 10.0
        pending = 0.0
        held_s = 0.0
        while True:
            v, w, done = controller.command(self.pose)
            if done:
                break
            if self.base.time_s > deadline:
                raise BlockedError(f"no progress: still {self._left(path):.1f} m from the goal")
            moved = self._step(v, w)
            pending += p.drive.dt_s
            held_s = held_s + p.drive.dt_s if moved != v else 0.0
            if held_s >= p.monitor_patience_s:
                # Something the monitor sees stands in the way: mark it and go round.
                held_s = 0.0
                round_it = self._replan_round(controller)
                controller = PurePursuit(round_it.resampled(0.05), goal_yaw, p.drive)
            if self.filter.needs_update(self.base.odom_pose):
                scan = self._update_filter()
                self._check_localization(scan)
                replanned = self._check_blocked(scan, controller)
                if replanned is not None:
                    controller = PurePursuit(replanned.resampled(0.05), goal_yaw, p.drive)
            if pending >= p.yield_every_s:
                yield pending
                pending = 0.0
        if pending:
            yield pending

    # -- one control tick in the (simulated) world ------------------------------------------
    def _step(self, v: float, w: float) -> float:
        """Advance the world and the base one tick; return the speed actually driven (0 when
        the collision monitor held the robot)."""
        dt = self.params.drive.dt_s
        world = self.world
        if world is not None:
            world.advance(dt, self.base.true_pose[:2])
            if v != 0.0 and self._monitor_blocks(v):
                v = 0.0
                self.safety.stops += 1
        self.base.step(v, w, dt)
        if world is not None:
            self.safety.observe(world.clearance_m(self.base.true_pose[:2]), self.base.true_pose)
        return v

    def _monitor_blocks(self, v: float) -> bool:
        p = self.params
        ranges = cast_rays(
            self.lidar.blocked, self.grid, self.base.true_pose, self.lidar.angles, p.monitor.range_m
        )
        return translation_blocked(
            ranges, self.lidar.angles, v, p.drive.dt_s, p.inflation.robot_radius, p.monitor
        )

    def _update_filter(self) -> LaserScan:
        assert self.filter is not None
        scan = self.lidar.scan(self.base.true_pose, self.rng)
        self.filter.update(self.base.odom_pose, scan, force=True)
        self._record()
        if self.world is not None:
            self.unmapped_shares.append(self._unmapped_share(scan))
        return scan

    def _unmapped_share(self, scan: LaserScan) -> float:
        """Share of the returns that ended on something the map lacks (shorter than the map
        would give by more than 10 cm)."""
        seen = scan.ranges < scan.range_max
        if not seen.any():
            return 0.0
        expected = cast_rays(
            self._map_blocked, self.grid, self.base.true_pose, scan.angles, scan.range_max
        )
        return float(np.mean(scan.ranges[seen] < expected[seen] - 0.1))

    # -- recovery ----------------------------------------------------------------------------
    def navigate(
        self, goal: tuple[float, float], goal_yaw: float | None, path: Path | None = None
    ) -> Iterator[float]:
        """Plan (or take ``path``) and drive to ``goal``, with the recovery sequence when the
        way is blocked; yields simulated seconds like ``follow``."""
        last: BlockedError | None = None
        for recovery in (None, *RECOVERIES):
            if recovery is not None:
                logger.info("blocked (%s); recovery: %s", last, recovery)
                self.recoveries.append(recovery)
                yield from self._recover(recovery)
            try:
                if path is None or recovery is not None:
                    path = self.plan(goal)
                yield from self.follow(path, goal_yaw)
            except BlockedError as exc:
                last = exc
            else:
                return
        raise self._gave_up(goal, last)

    def _recover(self, recovery: str) -> Iterator[float]:
        p = self.params
        if recovery == "clear the costmap":
            self.reset_obstacles()
            yield from self._stand(1.0)
        elif recovery == "rotate":
            yield from self._spin(2 * math.pi)
        elif recovery == "back up":
            yield from self._drive_straight(-p.backup_m, p.backup_speed_mps)
        else:
            yield from self._stand(p.recovery_wait_s)

    def _stand(self, seconds: float) -> Iterator[float]:
        ticks = max(1, round(seconds / self.params.drive.dt_s))
        for _ in range(ticks):
            self._step(0.0, 0.0)
        yield ticks * self.params.drive.dt_s

    def _spin(self, angle_rad: float) -> Iterator[float]:
        p = self.params.drive
        ticks = max(1, math.ceil(angle_rad / (p.max_turn_rate_rps * p.dt_s)))
        for _ in range(ticks):
            self._step(0.0, p.max_turn_rate_rps)
            if self.filter is not None and self.filter.needs_update(self.base.odom_pose):
                self._sense_obstacles(self._update_filter())
        yield ticks * p.dt_s

    def _drive_straight(self, distance_m: float, speed_mps: float) -> Iterator[float]:
        dt = self.params.drive.dt_s
        v = math.copysign(speed_mps, distance_m)
        ticks = max(1, math.ceil(abs(distance_m) / (speed_mps * dt)))
        for _ in range(ticks):
            if self._step(v, 0.0) == 0.0:
                break  # the monitor sees something behind: back up no further
            if self.filter is not None and self.filter.needs_update(self.base.odom_pose):
                self._sense_obstacles(self._update_filter())
        yield ticks * dt

    def _replan_round(self, controller: PurePursuit) -> Path:
        """Held by the monitor: mark what the scan sees now and plan round it."""
        self._sense_obstacles(self.lidar.scan(self.base.true_pose, self.rng))
        return self._replan_to(controller.path[-1], "something stands in the way to {goal}")

    def _replan_to(self, goal: FloatArray, blocked: str) -> Path:
        """A plan from here to ``goal`` on the live costmap; when there is none, BlockedError
        says ``blocked`` ({goal}: where to, {why}: the planner's reason)."""
        pose = self.pose
        try:
            return self._plan_on(
                self.planner, (float(pose[0]), float(pose[1])), (float(goal[0]), float(goal[1]))
            )
        except UnreachableError as exc:
            where = f"({goal[0]:.2f}, {goal[1]:.2f})"
            raise BlockedError(blocked.format(goal=where, why=exc)) from exc

    def _gave_up(self, goal: tuple[float, float], last: BlockedError | None) -> BlockedError:
        tried = ", ".join(RECOVERIES)
        doorway = self._closed_doorway(goal)
        if doorway is not None:
            return DoorClosedError(
                f"the way is blocked: the doorway at ({doorway[0]:.1f}, {doorway[1]:.1f}) on "
                f"the way to ({goal[0]:.2f}, {goal[1]:.2f}) is shut, and no other way leads there "
                f"(tried: {tried})"
            )
        return BlockedError(f"{last}; gave up after: {tried}")

    def _closed_doorway(self, goal: tuple[float, float]) -> tuple[float, float] | None:
        """Where the map's own way to ``goal`` crosses a doorway the seen obstacles shut."""
        if self.planner is self.map_planner or self.filter is None:
            return None
        pose = self.pose
        try:
            path = self.map_planner.plan((float(pose[0]), float(pose[1])), goal)
        except UnreachableError:
            return None
        grid = self.grid
        points = path.resampled(grid.resolution)
        ix, iy = grid.world_to_cell(points[:, 0], points[:, 1])
        static = self.map_planner.costmap
        shut = (self.costmap.costs[iy, ix] >= INSCRIBED) & (static.costs[iy, ix] < INSCRIBED)
        depth = max(1, round(self.params.doorway_depth_m / grid.resolution))
        tried = np.zeros(len(points), dtype=bool)
        for i in np.nonzero(shut)[0].tolist():
            # The way may cross the gap at a slant: try every 10 cm within reach of the block.
            for j in range(max(0, i - depth), min(len(points), i + depth + 1), 2):
                if not tried[j] and self._is_doorway(points[j]):
                    return float(points[j, 0]), float(points[j, 1])
                tried[j] = True
        return None

    def _is_doorway(self, centre: FloatArray) -> bool:
        """A gap in a wall: across its narrowest direction the map is at most
        2 x ``doorway_half_width_m`` wide here, and ``doorway_depth_m`` to either side of
        the gap line it is wider by ``doorway_opening_m`` at least on one side (a corridor
        keeps its width)."""
        p = self.params
        walls = self.grid.occupied
        angles = np.linspace(0.0, math.pi, 36, endpoint=False)
        both = np.r_[angles, angles + math.pi]
        reach = 2 * p.doorway_half_width_m + p.doorway_opening_m + 1.0

        def widths(at: FloatArray) -> FloatArray:
            r = cast_rays(walls, self.grid, np.array([at[0], at[1], 0.0]), both, reach)
            return np.asarray(r[: angles.size] + r[angles.size :])

        across = widths(centre)
        k = int(np.argmin(across))
        gap = float(across[k])
        if gap > 2 * p.doorway_half_width_m:
            return False
        normal = np.array([-math.sin(angles[k]), math.cos(angles[k])]) * p.doorway_depth_m
        side_widths = []
        for side in (centre + normal, centre - normal):
            r = cast_rays(
                walls,
                self.grid,
                np.array([side[0], side[1], 0.0]),
                np.array([angles[k], angles[k] + math.pi]),
                reach,
            )
            side_widths.append(float(r.sum()))
        return max(side_widths) >= gap + p.doorway_opening_m

    def _traverse(self, path: Path, goal_yaw: float | None) -> Iterator[float]:
        """Kinematic mode: the base moves along the path at full speed, no sensing."""
        p = self.params.drive
        duration = path.length_m / p.max_speed_mps
        end = path.points[-1]
        yaw = goal_yaw if goal_yaw is not None else float(self.base.true_pose[2])
        turn = abs(float(angle_diff(yaw, self.base.true_pose[2])))
        duration += turn / p.max_turn_rate_rps
        self.base.true_pose = np.array([end[0], end[1], yaw])
        self.base.odom_pose = self.base.true_pose.copy()
        self.base.time_s += duration
        self.base.odometer_m += path.length_m
        yield duration

    def _left(self, path: Path) -> float:
        pose = self.pose
        return math.hypot(path.points[-1][0] - pose[0], path.points[-1][1] - pose[1])

    def _record(self) -> None:
        assert self.filter is not None
        assert self.filter.estimate is not None
        self.tracking.append(
            TrackingSample(self.base.time_s, self.base.true_pose.copy(), self.filter.estimate.pose)
        )

    def _check_localization(self, scan: LaserScan) -> None:
        assert self.filter is not None

        ranges, angles = self.filter.usable_beams(scan)
        if ranges.size == 0:
            return
        distances = self.filter.field.endpoint_distances(self.pose, ranges, angles)
        near_wall = distances < 0.3
        expected = cast_rays(self._map_blocked, self.grid, self.pose, angles, scan.range_max)
        short = float(np.mean(~near_wall & (ranges < expected - 0.3)))
        matched = float(np.mean(near_wall)) + min(short, self.params.lost_short_allowance)
        bad = matched < self.params.lost_match_ratio or self.filter.localization_lost
        self._bad_matches = self._bad_matches + 1 if bad else 0
        if self._bad_matches >= self.params.lost_after_updates:
            raise LocalizationLostError(
                f"the scan no longer matches the map ({matched:.0%} of beams) near "
                f"({self.pose[0]:.2f}, {self.pose[1]:.2f})"
            )

    def _check_blocked(self, scan: LaserScan, controller: PurePursuit) -> Path | None:
        """Update the obstacle layer from the scan; if a marked obstacle now sits on the path
        ahead, replan round it (or raise BlockedError)."""
        self._sense_obstacles(scan)
        if self.planner is self.map_planner:
            return None
        ahead = controller.remaining
        travelled = np.r_[0.0, np.cumsum(np.hypot(*np.diff(ahead, axis=0).T))]
        ahead = ahead[travelled <= self.params.block_lookahead_m]
        grid = self.grid
        ix, iy = grid.world_to_cell(ahead[:, 0], ahead[:, 1])
        inside = (ix >= 0) & (ix < grid.width) & (iy >= 0) & (iy < grid.height)
        costs = self.costmap.costs[iy[inside], ix[inside]]
        static = self.map_planner.costmap.costs[iy[inside], ix[inside]]
        if not ((costs >= INSCRIBED) & (static < INSCRIBED)).any():
            return None
        logger.info("path blocked by %d marked cells; replanning", len(self.obstacles))
        return self._replan_to(controller.path[-1], "the way to {goal} is blocked: {why}")
