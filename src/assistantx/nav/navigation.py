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
  several updates in a row (fewer than ``lost_match_ratio`` of the beams end near a wall);
- BlockedError as well when the drive takes far longer than the path length warrants.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from weakref import WeakKeyDictionary

import numpy as np

from assistantx.core.errors import BlockedError, LocalizationLostError, UnreachableError
from assistantx.nav.amcl import AmclParams, ParticleFilter
from assistantx.nav.costmap import (
    INSCRIBED,
    Costmap,
    InflationParams,
    update_obstacles,
)
from assistantx.nav.diff_drive import DriveParams, PurePursuit, SimulatedBase
from assistantx.nav.geometry import FloatArray, angle_diff
from assistantx.nav.lidar import LaserScan, Lidar, LidarParams
from assistantx.nav.motion_model import OdometryNoise
from assistantx.nav.obstacle_layer import ObstacleLayer, ObstacleLayerParams
from assistantx.nav.occupancy_map import OccupancyMap
from assistantx.nav.plan_process import PLAN_PROCESS
from assistantx.nav.planner import GridPlanner, Path, PlannerParams

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class NavigationParams:
    amcl: AmclParams = field(default_factory=AmclParams)
    inflation: InflationParams = field(default_factory=InflationParams)
    planner: PlannerParams = field(default_factory=PlannerParams)
    drive: DriveParams = field(default_factory=DriveParams)
    lidar: LidarParams = field(default_factory=LidarParams)
    obstacles: ObstacleLayerParams = field(default_factory=ObstacleLayerParams)
    odometry_noise: OdometryNoise = field(
        default_factory=lambda: OdometryNoise(0.005, 0.005, 0.005, 0.005)
    )
    lost_match_ratio: float = 0.5  # share of beams that must end within 0.3 m of a wall
    lost_after_updates: int = 5
    block_lookahead_m: float = 1.5
    timeout_factor: float = 4.0  # give up after this multiple of the nominal driving time
    yield_every_s: float = 1.0
    # Plan in a worker process (plan_process): a search on a big map then never holds the
    # GIL of the process that serves requests. The service's robot turns it on.
    plan_in_process: bool = False


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
    ) -> None:
        self.params = params or NavigationParams()
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
            return self._plan_on(self.planner, start, goal)
        except UnreachableError as exc:
            if self.planner is self.map_planner:
                raise
            self._plan_on(self.map_planner, start, goal)  # raises if the map alone is the reason
            raise BlockedError(
                f"obstacles the robot sees block the way to ({goal[0]:.2f}, {goal[1]:.2f})"
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
        while True:
            v, w, done = controller.command(self.pose)
            if done:
                break
            if self.base.time_s > deadline:
                raise BlockedError(f"no progress: still {self._left(path):.1f} m from the goal")
            self.base.step(v, w, p.drive.dt_s)
            pending += p.drive.dt_s
            if self.filter.needs_update(self.base.odom_pose):
                scan = self.lidar.scan(self.base.true_pose, self.rng)
                self.filter.update(self.base.odom_pose, scan)
                self._record()
                self._check_localization(scan)
                replanned = self._check_blocked(scan, controller)
                if replanned is not None:
                    controller = PurePursuit(replanned.resampled(0.05), goal_yaw, p.drive)
            if pending >= p.yield_every_s:
                yield pending
                pending = 0.0
        if pending:
            yield pending

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
        matched = float(np.mean(distances < 0.3))
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
        pose = self.pose
        goal = controller.path[-1]
        try:
            return self._plan_on(
                self.planner, (float(pose[0]), float(pose[1])), (float(goal[0]), float(goal[1]))
            )
        except UnreachableError as exc:
            raise BlockedError(
                f"the way to ({goal[0]:.2f}, {goal[1]:.2f}) is blocked: {exc}"
            ) from exc
