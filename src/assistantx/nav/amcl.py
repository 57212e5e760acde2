"""Adaptive Monte Carlo Localization (nav2's amcl, vectorized over particles with numpy).

One filter update, run when the odometry has moved ``update_min_d`` metres or turned
``update_min_a`` radians since the last one:

1. motion_model: move every particle by the odometry step with the alpha1..alpha4 noise.
2. likelihood_field: weight each particle by its scan. The distance from every cell to the
   nearest obstacle is precomputed once (an exact EDT, clamped at
   ``laser_likelihood_max_dist``), and so is the per-cell log-likelihood of a beam ending there,
   ``log(z_hit * exp(-d^2 / (2 sigma_hit^2)) + z_rand / laser_max_range)``; a beam then costs
   one table lookup per particle. Beams are combined as a product (a sum of logs), the
   textbook model (Probabilistic Robotics table 6.3); up to ``max_beams`` evenly spaced beams are
   used and max-range readings are skipped, as in nav2. ``beam_product_exponent`` (not a nav2
   name; default 1) tempers the product for global localization and recovery. With
   ``do_beamskip`` (nav2's beam skipping), a beam whose endpoint lies within
   ``beam_skip_distance`` of a mapped obstacle for less than ``beam_skip_threshold`` of the
   (weighted) particles is left out for all of them: in a converged cloud that is a return
   from something the map lacks (a person, a moved box), which would otherwise pull the
   estimate towards a pose that explains it. If more than ``beam_skip_error_threshold`` of
   the beams would be skipped, the cloud does not agree on anything and every beam is used.
3. Every ``resample_interval`` updates, KLD-sampling with augmented-MCL recovery: a
   low-variance (systematic) resample draws ``max_particles`` candidates in O(N log N); with
   probability ``max(0, 1 - w_fast / w_slow)`` a candidate is replaced by a uniform random pose
   on free space; the candidates are shuffled and the shortest prefix that satisfies the KLD
   bound for the histogram bins it occupies (at least ``min_particles``) is kept.
4. The estimate: particles are grouped into clusters of adjacent histogram bins (0.5 m x
   0.5 m x 10 deg, heading wrapping round); the pose is the weighted mean of the heaviest
   cluster, with a circular mean and circular variance for the heading.

Departures from nav2, each a fix: resampling is O(N log N) rather than O(N^2) in the worst
case; the heading mean and variance are circular; when ``resample_interval > 1`` the weights
of updates without a resample are kept and multiplied by the next likelihood instead of being
reset; the recovery averages are not zeroed after each injection (amcl's reset stops the
injection after one resample, so a kidnapped robot rarely recovers); ``w_avg`` for recovery
is the weighted mean of the per-beam geometric-mean likelihood, so it does not jump when the
number of valid beams changes. ``pf_z`` is used directly as the normal quantile in the KLD
bound, as amcl does with its default 0.99.

All randomness comes from the ``numpy.random.Generator`` passed in.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import numpy.typing as npt

from assistantx.nav import disk_cache, map_transforms
from assistantx.nav.geometry import FloatArray, compose, relative, wrap_angle
from assistantx.nav.lidar import LaserScan
from assistantx.nav.motion_model import OdometryNoise, motion_model
from assistantx.nav.occupancy_map import FREE, OccupancyMap

_WEIGH_CHUNK = 10_000  # poses weighed at once by global_localization's first scan
LOST_W_RATIO = 0.9  # w_fast / w_slow below this is "lost": measured 1.0 while tracking and
# 0.8-0.9 a few seconds after a kidnap in a small room (tests/nav/test_amcl.py)


@dataclass(frozen=True)
class AmclParams:
    """nav2 amcl parameter names and defaults (those that the likelihood-field model uses)."""

    alpha1: float = 0.2
    alpha2: float = 0.2
    alpha3: float = 0.2
    alpha4: float = 0.2
    laser_likelihood_max_dist: float = 2.0
    laser_max_range: float = 100.0
    laser_min_range: float = -1.0
    max_beams: int = 60
    max_particles: int = 2000
    min_particles: int = 500
    pf_err: float = 0.05
    pf_z: float = 0.99
    recovery_alpha_fast: float = 0.0
    recovery_alpha_slow: float = 0.0
    resample_interval: int = 1
    sigma_hit: float = 0.2
    update_min_a: float = 0.2
    update_min_d: float = 0.25
    z_hit: float = 0.5
    z_rand: float = 0.5
    # Not in nav2: the exponent on the beam product (1 = the textbook product). Beams of one
    # scan are not independent, so the product is overconfident; a smaller value keeps more
    # hypotheses alive while the cloud is spread (global localization, recovery).
    beam_product_exponent: float = 1.0
    do_beamskip: bool = False
    # Not in nav2: selective resampling (Doucet; GMapping's Neff test). With a value r > 0 a
    # resample due by resample_interval happens only when the effective sample size
    # 1 / sum(w^2) is below r times the particle count. Evidence that does not favour one
    # of several look-alike places leaves their weights even and Neff high, so no resample
    # thins one of them out by chance (0 = resample whenever due, as nav2).
    resample_min_neff_ratio: float = 0.0
    # Not in nav2: measure distances to the unknown rim of the known floor too (the grey edge
    # of a SLAM map is a wall seen edge-on, and the world's beams end there).
    unknown_rim_is_wall: bool = False
    beam_skip_distance: float = 0.5
    beam_skip_threshold: float = 0.3
    beam_skip_error_threshold: float = 0.9
    # amcl's KLD histogram (pf_kdtree) bin sizes.
    bin_size_xy: float = 0.5
    bin_size_yaw: float = math.radians(10.0)

    def __post_init__(self) -> None:
        if not 0 < self.min_particles <= self.max_particles:
            raise ValueError("need 0 < min_particles <= max_particles")
        if self.resample_interval < 1 or self.max_beams < 2:
            raise ValueError("resample_interval must be >= 1 and max_beams >= 2")

    @property
    def odometry_noise(self) -> OdometryNoise:
        return OdometryNoise(self.alpha1, self.alpha2, self.alpha3, self.alpha4)


@dataclass(frozen=True)
class PoseEstimate:
    x: float
    y: float
    yaw: float
    covariance: FloatArray  # 3x3; [2, 2] is the circular variance of the heading
    cluster_weight: float  # share of the total weight in the chosen cluster

    @property
    def pose(self) -> FloatArray:
        return np.array([self.x, self.y, self.yaw])

    @property
    def position_std_m(self) -> float:
        return math.sqrt(max(0.0, float(self.covariance[0, 0] + self.covariance[1, 1])))


class LikelihoodField:
    """Per-cell log-likelihood of a beam endpoint, and the free cells for random poses."""

    def __init__(self, grid: OccupancyMap, params: AmclParams) -> None:
        self.grid = grid
        occupied = grid.data >= 65
        if params.unknown_rim_is_wall:
            occupied = occupied | grid.unknown_rim
        # Both tables are kept in the map cache by what they are made from (the obstacles,
        # the cell size, the beam model) and mapped from there, read-only, on a later start:
        # computing them was most of a robot's set-up on a big map (~0.1 CPU-s on nav2's
        # warehouse), and the filter's lookups read a few of their pages at a time.
        inputs = (occupied.shape, np.packbits(occupied).tobytes(), grid.resolution)
        max_dist = params.laser_likelihood_max_dist
        distance = disk_cache.cached_array(
            "endpoint-distance",
            (*inputs, max_dist),
            lambda: np.minimum(_distance_to(occupied) * grid.resolution, max_dist),
            mapped=True,
        )
        beam_model = (max_dist, params.z_hit, params.sigma_hit, params.z_rand)
        log_p = disk_cache.cached_array(
            "endpoint-log-likelihood",
            (*inputs, *beam_model, params.laser_max_range),
            lambda: self._log_likelihood(distance, params),
            mapped=True,
        )
        self.distance_m = distance.ravel()
        self.log_p = log_p.ravel()
        self.log_p_off_map = float(self._log_likelihood(np.array(max_dist), params))

    @cached_property
    def _free_cells(self) -> tuple[FloatArray, FloatArray]:
        """The free cells' centres (x, y), for random poses: made for the first global
        localization, not with the field (a service starts from a known pose; on nav2's
        warehouse, 1.4 M free cells, they were ~0.1 CPU-s of every start, most of it the
        first touch of their fresh memory)."""
        free_iy, free_ix = np.nonzero(self.grid.data == FREE)
        return self.grid.cell_to_world(free_ix, free_iy)

    @property
    def free_x(self) -> FloatArray:
        return self._free_cells[0]

    @property
    def free_y(self) -> FloatArray:
        return self._free_cells[1]

    @staticmethod
    def _log_likelihood(distance: FloatArray, params: AmclParams) -> FloatArray:
        p_hit = params.z_hit * np.exp(-(distance**2) / (2 * params.sigma_hit**2))
        return np.asarray(np.log(p_hit + params.z_rand / params.laser_max_range))

    def beam_log_likelihood(
        self, poses: FloatArray, ranges: FloatArray, angles: FloatArray
    ) -> FloatArray:
        """log p(scan | pose) for each pose (n,), beams combined as a product."""
        return np.asarray(self.per_beam(poses, ranges, angles)[0].sum(axis=1))

    def per_beam(
        self, poses: FloatArray, ranges: FloatArray, angles: FloatArray
    ) -> tuple[FloatArray, FloatArray]:
        """Per pose and beam (n, beams): log p(beam | pose), and the endpoint's distance
        (m, clamped) to the nearest mapped obstacle."""
        grid = self.grid
        cos_yaw, sin_yaw = np.cos(poses[:, 2:3]), np.sin(poses[:, 2:3])
        bx, by = ranges * np.cos(angles), ranges * np.sin(angles)  # endpoints, robot frame
        ex = poses[:, 0:1] + cos_yaw * bx - sin_yaw * by
        ey = poses[:, 1:2] + sin_yaw * bx + cos_yaw * by
        gx, gy = grid.to_grid_frame(ex, ey)
        ix = np.floor(gx * (1 / grid.resolution)).astype(np.int64)
        iy = np.floor(gy * (1 / grid.resolution)).astype(np.int64)
        inside = (ix >= 0) & (ix < grid.width) & (iy >= 0) & (iy < grid.height)
        flat = np.where(inside, iy * grid.width + ix, 0)
        log_p = np.where(inside, self.log_p[flat], self.log_p_off_map)
        distance = np.where(inside, self.distance_m[flat], self._farthest_m)
        return np.asarray(log_p), np.asarray(distance)

    @cached_property
    def _farthest_m(self) -> float:
        """The largest distance in the field (an endpoint off the map is that far): found
        once, not by reading the whole table at every scan."""
        return float(self.distance_m.max(initial=0.0))

    def endpoint_distances(
        self, pose: FloatArray, ranges: FloatArray, angles: FloatArray
    ) -> FloatArray:
        """Distance (m, clamped) from each beam endpoint of one pose to the nearest obstacle."""
        grid = self.grid
        heading = pose[2] + angles
        ix, iy = grid.world_to_cell(
            pose[0] + ranges * np.cos(heading), pose[1] + ranges * np.sin(heading)
        )
        inside = (ix >= 0) & (ix < grid.width) & (iy >= 0) & (iy < grid.height)
        flat = np.where(inside, iy * grid.width + ix, 0)
        return np.where(inside, self.distance_m[flat], np.inf)

    def random_poses(self, n: int, rng: np.random.Generator) -> FloatArray:
        pick = rng.integers(0, self.free_x.size, n)
        jitter = rng.uniform(-0.5, 0.5, (2, n)) * self.grid.resolution
        return np.column_stack(
            [
                self.free_x[pick] + jitter[0],
                self.free_y[pick] + jitter[1],
                rng.uniform(-math.pi, math.pi, n),
            ]
        )


# -- resampling and KLD --------------------------------------------------------------------
def low_variance_resample(
    weights: FloatArray, n: int, rng: np.random.Generator
) -> npt.NDArray[np.int64]:
    """Systematic resampling: indices of ``n`` draws, one uniform offset, O(n log N)."""
    cumulative = np.cumsum(weights)
    cumulative /= cumulative[-1]
    positions = (rng.random() + np.arange(n)) / n
    idx = np.searchsorted(cumulative, positions, side="right")
    return np.minimum(idx, len(weights) - 1).astype(np.int64)


def kld_sample_count(bins: npt.ArrayLike, pf_err: float, pf_z: float) -> FloatArray:
    """Particles needed so that the KL divergence to the true posterior stays below pf_err
    with the quantile pf_z, given ``bins`` occupied histogram bins (Fox 2003)."""
    k = np.asarray(bins, dtype=float)
    km1 = np.maximum(k - 1, 1.0)
    a = 2.0 / (9.0 * km1)
    n = km1 / (2.0 * pf_err) * (1.0 - a + np.sqrt(a) * pf_z) ** 3
    return np.where(k <= 1, 1.0, n)


def histogram_bins(poses: FloatArray, params: AmclParams) -> npt.NDArray[np.int64]:
    """Integer key of each pose's (x, y, yaw) histogram bin."""
    ix = np.floor(poses[:, 0] / params.bin_size_xy).astype(np.int64) + (1 << 19)
    iy = np.floor(poses[:, 1] / params.bin_size_xy).astype(np.int64) + (1 << 19)
    yaw_bins = round(2 * math.pi / params.bin_size_yaw)
    it = np.floor(np.mod(poses[:, 2], 2 * math.pi) / params.bin_size_yaw).astype(np.int64)
    it = np.minimum(it, yaw_bins - 1)
    return (ix << 26) | (iy << 6) | it


def kld_prefix_length(keys: npt.NDArray[np.int64], params: AmclParams) -> int:
    """Shortest prefix of the (shuffled) candidates that meets the KLD bound."""
    m = keys.size
    _, first = np.unique(keys, return_index=True)
    new_bin = np.zeros(m, dtype=bool)
    new_bin[first] = True
    bins_so_far = np.cumsum(new_bin)
    needed = np.maximum(
        kld_sample_count(bins_so_far, params.pf_err, params.pf_z), params.min_particles
    )
    counts = np.arange(1, m + 1)
    enough = np.nonzero(counts >= needed)[0]
    return int(enough[0]) + 1 if enough.size else m


def cluster_labels(keys: npt.NDArray[np.int64], params: AmclParams) -> npt.NDArray[np.int64]:
    """Label particles by connected groups of occupied histogram bins (26-neighbourhood,
    heading wrapping round)."""
    unique, inverse = np.unique(keys, return_inverse=True)
    k = unique.size
    yaw_bins = round(2 * math.pi / params.bin_size_yaw)
    ix, iy, it = unique >> 26, (unique >> 6) & ((1 << 20) - 1), unique & 63
    rows, cols = [np.arange(k)], [np.arange(k)]
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            for dt in (-1, 0, 1):
                if (dx, dy, dt) <= (0, 0, 0):
                    continue  # each undirected pair once
                nkey = ((ix + dx) << 26) | ((iy + dy) << 6) | np.mod(it + dt, yaw_bins)
                pos = np.minimum(np.searchsorted(unique, nkey), k - 1)
                hit = unique[pos] == nkey
                rows.append(np.nonzero(hit)[0])
                cols.append(pos[hit])
    roots = _connected_roots(k, np.concatenate(rows), np.concatenate(cols))
    _, labels = np.unique(roots, return_inverse=True)  # numbered by each group's first bin
    return np.asarray(labels.reshape(-1)[inverse], dtype=np.int64)


def _connected_roots(
    k: int, a: npt.NDArray[np.intp], b: npt.NDArray[np.intp]
) -> npt.NDArray[np.intp]:
    """For each of ``k`` nodes joined by the edges ``a[i]``-``b[i]``, the smallest node of
    its connected group. Each round hooks every edge's larger root under the smaller one,
    then follows pointers until each points at its root (a few rounds for the filter's bins;
    no scipy.sparse import, about a fifth of a CPU-second, for what is a few thousand bins)."""
    parent = np.arange(k)
    while True:
        ra, rb = parent[a], parent[b]
        apart = ra != rb
        if not apart.any():
            return parent
        low = np.minimum(ra[apart], rb[apart])
        np.minimum.at(parent, ra[apart], low)
        np.minimum.at(parent, rb[apart], low)
        while True:  # parent[x] <= x always, so this ends
            jumped = parent[parent]
            if np.array_equal(jumped, parent):
                break
            parent = jumped


def weighted_pose_stats(poses: FloatArray, weights: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Weighted mean and covariance; the heading uses the circular mean and variance."""
    w = weights / weights.sum()
    mx, my = float(w @ poses[:, 0]), float(w @ poses[:, 1])
    c, s = float(w @ np.cos(poses[:, 2])), float(w @ np.sin(poses[:, 2]))
    resultant = min(1.0, math.hypot(c, s))
    cov = np.zeros((3, 3))
    dx, dy = poses[:, 0] - mx, poses[:, 1] - my
    cov[0, 0], cov[1, 1] = float(w @ (dx * dx)), float(w @ (dy * dy))
    cov[0, 1] = cov[1, 0] = float(w @ (dx * dy))
    cov[2, 2] = -2.0 * math.log(max(resultant, 1e-12))  # circular variance, rad^2
    return np.array([mx, my, math.atan2(s, c)]), cov


# -- the filter ----------------------------------------------------------------------------
@dataclass
class _RecoveryState:
    """Exponential averages of w_avg in the log domain, started from zero and bias-corrected
    (divided by 1 - (1 - alpha)^t): early on each is the plain mean so far, so w_slow does not
    stay pinned to the first, poorly converged value for 1 / alpha_slow updates."""

    log_w_slow: float | None = None
    log_w_fast: float | None = None
    count: int = 0
    _raw_slow: float = -math.inf
    _raw_fast: float = -math.inf

    def add(self, log_w_avg: float, alpha_slow: float, alpha_fast: float) -> None:
        self.count += 1
        self._raw_slow = _smooth_log(self._raw_slow, log_w_avg, alpha_slow)
        self._raw_fast = _smooth_log(self._raw_fast, log_w_avg, alpha_fast)
        self.log_w_slow = self._raw_slow - math.log1p(-((1 - alpha_slow) ** self.count))
        self.log_w_fast = self._raw_fast - math.log1p(-((1 - alpha_fast) ** self.count))


@dataclass
class ParticleFilter:
    grid: OccupancyMap
    params: AmclParams
    rng: np.random.Generator
    particles: FloatArray = field(init=False)
    log_weights: FloatArray = field(init=False)
    updates: int = field(init=False, default=0)
    estimate: PoseEstimate | None = field(init=False, default=None)

    def __post_init__(self) -> None:
        self.field = LikelihoodField(self.grid, self.params)
        self._recovery = _RecoveryState()
        self._odom_at_update: FloatArray | None = None
        self._pose_at_update: FloatArray | None = None
        self._since_resample = 0
        self.particles = np.zeros((0, 3))
        self.log_weights = np.zeros(0)

    # -- initialisation -------------------------------------------------------------------
    def initialize(
        self,
        pose: FloatArray,
        covariance_diag: tuple[float, float, float] = (0.25, 0.25, (math.pi / 12) ** 2),
    ) -> None:
        """A Gaussian cloud around ``pose`` (nav2's initial_pose defaults)."""
        n = self.params.max_particles
        sd = np.sqrt(np.asarray(covariance_diag))
        cloud = np.asarray(pose, dtype=float) + self.rng.standard_normal((n, 3)) * sd
        cloud[:, 2] = wrap_angle(cloud[:, 2])
        self._reset(cloud)

    def global_localization(self, scan: LaserScan | None = None, oversample: int = 1) -> None:
        """Spread ``max_particles`` uniformly over the free space of the map. With a ``scan``
        and ``oversample`` k > 1, ``k * max_particles`` uniform poses are weighed by that scan
        (the tempered product) and ``max_particles`` drawn from them: on a big map a uniform
        cloud often has no particle close enough to the truth to win, and then gathers on
        the best wrong place; drawing from k times as many poses puts k times as many near
        every place the scan fits."""
        n = self.params.max_particles
        if scan is None or oversample <= 1:
            self._reset(self.field.random_poses(n, self.rng))
            return
        candidates = self.field.random_poses(n * oversample, self.rng)
        ranges, angles = self.usable_beams(scan)
        if ranges.size == 0:
            self._reset(candidates[:n])
            return
        # weighed in chunks: the beam model's per-pose-per-beam arrays of all k * n poses at
        # once took about a gigabyte on a 20,000-particle cloud; a pose's weight does not
        # depend on the others, so chunks give the same weights
        log_w = self.params.beam_product_exponent * np.concatenate(
            [
                self.field.beam_log_likelihood(candidates[k : k + _WEIGH_CHUNK], ranges, angles)
                for k in range(0, len(candidates), _WEIGH_CHUNK)
            ]
        )
        weights = np.exp(log_w - log_w.max())
        self._reset(candidates[low_variance_resample(weights, n, self.rng)])

    def _reset(self, cloud: FloatArray) -> None:
        self.particles = cloud
        self.log_weights = np.full(len(cloud), -math.log(len(cloud)))
        self._odom_at_update = None
        self._recovery = _RecoveryState()
        self._since_resample = 0
        self.estimate = self._estimate()

    def drop(self, ruled_out: npt.NDArray[np.bool_]) -> None:
        """Remove the particles at places shown not to be the robot's (kept if that would
        leave none): a check the likelihood field cannot make has ruled them out."""
        if ruled_out.all() or not ruled_out.any():
            return
        keep = ~ruled_out
        self.particles = self.particles[keep]
        self.log_weights = self.log_weights[keep] - logsumexp(self.log_weights[keep])
        self.estimate = self._estimate()
        self._pose_at_update = self.estimate.pose

    # -- updates --------------------------------------------------------------------------
    def pose_from_odometry(self, odom: FloatArray) -> FloatArray:
        """The map pose now: the last estimate moved by the odometry since that update."""
        if self.estimate is None:
            raise RuntimeError("filter not initialised")
        if self._odom_at_update is None or self._pose_at_update is None:
            return self.estimate.pose
        return compose(self._pose_at_update, relative(odom, self._odom_at_update))

    def needs_update(self, odom: FloatArray) -> bool:
        if self._odom_at_update is None:
            return True
        step = relative(odom, self._odom_at_update)
        return bool(
            math.hypot(step[0], step[1]) >= self.params.update_min_d
            or abs(step[2]) >= self.params.update_min_a
        )

    def update(self, odom: FloatArray, scan: LaserScan, *, force: bool = False) -> bool:
        """Run one filter update if the base moved enough (or ``force``); True if it ran."""
        if not (force or self.needs_update(odom)):
            return False
        if self._odom_at_update is not None:
            self.particles = motion_model(
                self.particles, self._odom_at_update, odom, self.params.odometry_noise, self.rng
            )
        self.sensor_update(scan)
        self.estimate = self._estimate()
        self._since_resample += 1
        if self._since_resample >= self.params.resample_interval and self._weights_uneven():
            self.resample()
            self._since_resample = 0
        self._odom_at_update = np.asarray(odom, dtype=float).copy()
        self._pose_at_update = self.estimate.pose
        self.updates += 1
        return True

    def _weights_uneven(self) -> bool:
        ratio = self.params.resample_min_neff_ratio
        if ratio <= 0:
            return True
        w = np.exp(self.log_weights - logsumexp(self.log_weights))
        return bool(1.0 / float(w @ w) < ratio * w.size)

    def sensor_update(self, scan: LaserScan) -> None:
        ranges, angles = self.usable_beams(scan)
        if ranges.size == 0:
            return
        prior = self.log_weights - logsumexp(self.log_weights)
        per_beam, distance = self.field.per_beam(self.particles, ranges, angles)
        if self.params.do_beamskip:
            keep = self._beams_agreed_on(distance, np.exp(prior))
            per_beam, ranges = per_beam[:, keep], ranges[keep]
        log_likelihood = np.asarray(per_beam.sum(axis=1))
        # Recovery statistic: weighted mean of the per-beam geometric-mean likelihood.
        log_w_avg = float(logsumexp(prior + log_likelihood / ranges.size))
        self._track_recovery(log_w_avg)
        posterior = prior + self.params.beam_product_exponent * log_likelihood
        self.log_weights = posterior - logsumexp(posterior)

    def _beams_agreed_on(self, distance: FloatArray, weights: FloatArray) -> npt.NDArray[np.bool_]:
        """nav2's beam skip: the beams that end near a mapped obstacle for enough of the
        weight (all of them if too few would be left)."""
        p = self.params
        agree = weights @ (distance < p.beam_skip_distance)
        keep = np.asarray(agree >= p.beam_skip_threshold)
        if 1.0 - keep.mean() > p.beam_skip_error_threshold:
            return np.ones_like(keep)
        return keep

    def usable_beams(self, scan: LaserScan) -> tuple[FloatArray, FloatArray]:
        p = self.params
        range_max = min(scan.range_max, p.laser_max_range)
        range_min = max(scan.range_min, p.laser_min_range)
        count = scan.ranges.size
        step = max(1, (count - 1) // (p.max_beams - 1)) if count > 1 else 1
        idx = np.arange(0, count, step)[: p.max_beams]
        ranges, angles = scan.ranges[idx], scan.angles[idx]
        ok = np.isfinite(ranges) & (ranges < range_max) & (ranges > range_min)
        return ranges[ok], angles[ok]

    def _track_recovery(self, log_w_avg: float) -> None:
        p = self.params
        if p.recovery_alpha_slow <= 0 or p.recovery_alpha_fast <= 0:
            return
        self._recovery.add(log_w_avg, p.recovery_alpha_slow, p.recovery_alpha_fast)

    @property
    def random_pose_probability(self) -> float:
        """max(0, 1 - w_fast / w_slow): the share of resampled particles drawn at random."""
        state = self._recovery
        if state.log_w_slow is None or state.log_w_fast is None:
            return 0.0
        return max(0.0, 1.0 - math.exp(min(0.0, state.log_w_fast - state.log_w_slow)))

    @property
    def localization_lost(self) -> bool:
        """The localization-lost signal: the short-term average likelihood has fallen below
        ``LOST_W_RATIO`` of the long-term one (w_fast / w_slow), i.e. the scans have stopped
        fitting the map where the particles are. Only with recovery on (both
        recovery_alpha_* > 0, as nav2); a caller can stop, re-localize or ask for help."""
        return self.random_pose_probability > 1.0 - LOST_W_RATIO

    def resample(self) -> None:
        """KLD-sampling with augmented-MCL random poses; weights become uniform."""
        p = self.params
        weights = np.exp(self.log_weights - self.log_weights.max())
        candidates = self.particles[low_variance_resample(weights, p.max_particles, self.rng)]
        inject = self.random_pose_probability
        if inject > 0:
            replace = self.rng.random(p.max_particles) < inject
            candidates[replace] = self.field.random_poses(int(replace.sum()), self.rng)
        candidates = candidates[self.rng.permutation(p.max_particles)]
        n = kld_prefix_length(histogram_bins(candidates, p), p)
        self.particles = candidates[:n].copy()
        self.log_weights = np.full(n, -math.log(n))

    def _estimate(self) -> PoseEstimate:
        weights = np.exp(self.log_weights - self.log_weights.max())
        labels = cluster_labels(histogram_bins(self.particles, self.params), self.params)
        totals = np.bincount(labels, weights=weights)
        best = int(np.argmax(totals))
        members = labels == best
        mean, cov = weighted_pose_stats(self.particles[members], weights[members])
        share = float(totals[best] / totals.sum())
        return PoseEstimate(float(mean[0]), float(mean[1]), float(mean[2]), cov, share)

    def sample(self, n: int) -> FloatArray:
        """Up to ``n`` particles, drawn by weight without replacement bias (for display)."""
        if len(self.particles) <= n:
            return self.particles.copy()
        weights = np.exp(self.log_weights - self.log_weights.max())
        return self.particles[low_variance_resample(weights, n, self.rng)]


def _smooth_log(previous: float, value: float, alpha: float) -> float:
    """log((1 - alpha) * exp(previous) + alpha * exp(value))."""
    return float(np.logaddexp(math.log1p(-alpha) + previous, math.log(alpha) + value))


def _distance_to(occupied: npt.NDArray[np.bool_]) -> npt.NDArray[np.float64]:
    """Each cell's distance (cells) to the nearest occupied one (inf: none on the map)."""
    return map_transforms.distance_to(occupied)


def logsumexp(values: npt.NDArray[np.float64]) -> float:
    """log(sum(exp(values))) without overflow (scipy.special's, for one flat array: importing
    scipy.special cost the service's start a few tenths of a CPU-second)."""
    top = float(np.max(values))
    if not math.isfinite(top):
        return top
    return top + math.log(float(np.sum(np.exp(values - top))))
