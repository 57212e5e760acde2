"""A simulated differential-drive base and the pure-pursuit controller that follows a path.

The base keeps the *true* pose (integrated exactly along circular arcs) and an odometry
pose that drifts: each control tick's true step is passed through the odometry motion model
with the base's own (small) alphas, as wheel slip and encoder error would corrupt it.
Simulated time advances by ``dt_s`` per tick.

The controller is pure pursuit (Coulter 1992): steer towards the path point ``lookahead_m``
ahead with curvature ``2 sin(alpha) / L``; turn in place when that point is far off the
heading; slow down for the last half metre; finally turn to the goal heading.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from assistantx.nav.geometry import FloatArray, angle_diff, compose, wrap_angle
from assistantx.nav.motion_model import OdometryNoise, motion_model


@dataclass(frozen=True)
class DriveParams:
    max_speed_mps: float = 0.5
    max_turn_rate_rps: float = 1.5
    lookahead_m: float = 0.5
    goal_tolerance_m: float = 0.05
    yaw_tolerance_rad: float = 0.05
    rotate_in_place_rad: float = math.radians(50)
    slow_down_m: float = 0.5
    dt_s: float = 0.1


def integrate(pose: FloatArray, v: float, w: float, dt: float) -> FloatArray:
    """Exact unicycle motion for ``dt`` seconds at speed v (m/s) and turn rate w (rad/s)."""
    if abs(w) < 1e-9:
        step = np.array([v * dt, 0.0, 0.0])
    else:
        radius = v / w
        dtheta = w * dt
        step = np.array([radius * math.sin(dtheta), radius * (1 - math.cos(dtheta)), dtheta])
    return compose(pose, step)


@dataclass
class PurePursuit:
    path: FloatArray  # (n, 2) densely resampled, metres
    goal_yaw: float | None
    params: DriveParams = field(default_factory=DriveParams)
    _progress: int = 0
    # Path length from each point to the end: the goal counts as reached only once the
    # robot has come along the path to its last stretch, so a route that ends where it
    # starts (a tour back to its first stop) is driven, not declared done at once.
    _to_end: FloatArray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        steps = np.hypot(*np.diff(self.path, axis=0).T) if len(self.path) > 1 else np.zeros(0)
        self._to_end = np.r_[np.cumsum(steps[::-1])[::-1], 0.0]

    @property
    def remaining(self) -> FloatArray:
        """The part of the path not yet passed."""
        return self.path[self._progress :]

    def command(self, pose: FloatArray) -> tuple[float, float, bool]:
        """(v m/s, w rad/s, done) for the robot at ``pose``."""
        p = self.params
        goal = self.path[-1]
        # Progress along the path only moves forward (the nearest point in a short window).
        window = self.path[self._progress : self._progress + 40]
        d = np.hypot(window[:, 0] - pose[0], window[:, 1] - pose[1])
        self._progress += int(np.argmin(d))
        to_goal = math.hypot(goal[0] - pose[0], goal[1] - pose[1])
        on_last_stretch = self._to_end[self._progress] <= p.lookahead_m
        if to_goal <= p.goal_tolerance_m and on_last_stretch:
            if self.goal_yaw is None:
                return 0.0, 0.0, True
            err = float(angle_diff(self.goal_yaw, pose[2]))
            if abs(err) <= p.yaw_tolerance_rad:
                return 0.0, 0.0, True
            return 0.0, _turn_rate(err, p), False
        ahead = self.path[self._progress :]
        dist = np.hypot(ahead[:, 0] - pose[0], ahead[:, 1] - pose[1])
        beyond = np.nonzero(dist >= p.lookahead_m)[0]
        target = ahead[beyond[0]] if beyond.size else goal
        alpha = float(angle_diff(math.atan2(target[1] - pose[1], target[0] - pose[0]), pose[2]))
        if abs(alpha) > p.rotate_in_place_rad:
            return 0.0, _turn_rate(alpha, p), False
        left = max(to_goal, float(self._to_end[self._progress]))
        v = p.max_speed_mps * min(1.0, max(0.2, left / p.slow_down_m))
        distance = max(math.hypot(target[0] - pose[0], target[1] - pose[1]), 1e-6)
        w = 2.0 * v * math.sin(alpha) / distance
        limit = p.max_turn_rate_rps
        if abs(w) > limit:  # keep the curvature by slowing down
            v *= limit / abs(w)
            w = math.copysign(limit, w)
        return v, w, False


def _turn_rate(err: float, p: DriveParams) -> float:
    return math.copysign(min(p.max_turn_rate_rps, max(0.2, 2.0 * abs(err))), err)


@dataclass
class SimulatedBase:
    """True pose, drifting odometry and a simulated clock of a differential-drive base."""

    true_pose: FloatArray
    rng: np.random.Generator
    odometry_noise: OdometryNoise = field(
        default_factory=lambda: OdometryNoise(0.005, 0.005, 0.005, 0.005)
    )
    time_s: float = 0.0
    odometer_m: float = 0.0
    odom_pose: FloatArray = field(init=False)

    def __post_init__(self) -> None:
        self.true_pose = np.asarray(self.true_pose, dtype=float)
        # The odometry frame starts where the robot is; only its increments matter.
        self.odom_pose = self.true_pose.copy()

    def step(self, v: float, w: float, dt: float) -> None:
        before = self.true_pose
        self.true_pose = integrate(before, v, w, dt)
        self.odom_pose = motion_model(
            self.odom_pose[None, :], before, self.true_pose, self.odometry_noise, self.rng
        )[0]
        self.time_s += dt
        self.odometer_m += abs(v) * dt

    def teleport(self, pose: FloatArray) -> None:
        """Kidnap the robot: the true pose jumps, the odometry does not notice."""
        self.true_pose = np.asarray(pose, dtype=float).copy()
        self.true_pose[2] = float(wrap_angle(self.true_pose[2]))
