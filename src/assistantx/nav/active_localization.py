"""Global localization by moving: the robot turns and drives while AMCL updates, until the
particle cloud has gathered into one tight cluster that explains the scan, or a bounded
exploration has not told the candidate places apart (then it says so instead of guessing).

One scan cannot tell a pose from a look-alike one (a room turned half round, a corridor
whose ends lie beyond the LiDAR's range). Moving can: from a few metres away one of the
candidates sees a wall, a pillar or a doorway the other does not. This is what nav2 users do
(``/reinitialize_global_localization``, then spin and drive about): here the robot first turns
once in place, then drives short legs into free space it picks from its own scan, each leg
towards the direction that takes it furthest from where it has already been (odometry frame;
no map pose is needed to choose). The filter updates on its usual odometry thresholds while
it moves.

Convergence (AMCL's idea of a converged filter, with two checks added): the heaviest cluster
holds at least ``converged_share`` of the weight, its position spread (1 sigma) is at most
``converged_std_m`` and its heading spread at most ``converged_yaw_std_rad``; the scan fits
the map at the estimate (refined by a few scan-matching steps) by the beam model:
``converged_fit`` of the beams within ``fit_distance_m`` of the ray-cast range; and no
rival place the cloud held earlier is still open (rival_places: a look-alike that chance,
not the scans, took out of the cloud). All of this for ``settle_updates`` updates in a row.
A cloud split between places never passes, so its estimate is never declared. A cloud that
has gathered where the scan does not fit is spread over the map again (``respread``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Protocol

import numpy as np

from assistantx.nav.amcl import (
    AmclParams,
    ParticleFilter,
    PoseEstimate,
    cluster_labels,
    histogram_bins,
)
from assistantx.nav.diff_drive import SimulatedBase
from assistantx.nav.geometry import FloatArray, angle_diff
from assistantx.nav.lidar import LaserScan, Lidar
from assistantx.nav.rival_places import RivalPlaces, beam_fit, refine


@dataclass(frozen=True)
class ExploreParams:
    speed_mps: float = 0.3
    turn_rate_rps: float = 1.0
    dt_s: float = 0.1
    spin_rad: float = 2 * math.pi  # the first, in-place turn
    leg_m: float = 1.0  # one drive into free space
    robot_radius_m: float = 0.25
    clearance_m: float = 0.1  # free space kept beyond the robot's sides and the leg's end
    shortest_leg_m: float = 0.25  # where a full leg does not fit, halve it down to this
    headings: int = 36  # candidate directions per leg
    max_updates: int = 200  # filter updates before giving up
    converged_share: float = 0.95
    # AMCL calls a cloud converged when every particle is within 0.5 m of the mean; these
    # are 1-sigma bounds of the heaviest cluster, tighter than that.
    converged_std_m: float = 0.2
    converged_yaw_std_rad: float = math.radians(8.0)
    # The fit is what tells a look-alike place apart once the cloud has gathered there:
    # measured on tb3_sandbox, a pose turned a quarter round among its pillars fits 95% of
    # the beams within 0.3 m but only 55-80% within 0.1 m; the true pose, 95-100%.
    fit_distance_m: float = 0.1
    converged_fit: float = 0.9
    # The cloud is drawn from this many times max_particles uniform poses, weighed by the
    # first scan (ParticleFilter.global_localization).
    oversample: int = 10
    settle_updates: int = 3
    # A cloud gathered in one tight cluster whose scan does not fit the map for this many
    # updates has settled on a wrong place (no particle near the truth survived the first
    # updates); it is spread over the map again from where the robot now stands.
    respread_after_updates: int = 5
    mode_share: float = 0.05  # a cluster with this much of the weight counts as a candidate
    # The pose declared is the cloud's mean, so it must stand where the scan fits: within
    # ``centred_m`` and ``centred_yaw_rad`` of the scan-matched place. A tight cloud can sit
    # beside it (on depot, 0.26 m off with a 5 cm spread, after the particles nearest the
    # truth died out); it is then drawn again about the matched place (sensor resetting,
    # Lenser and Veloso 2000), ``recentre_std_m`` and ``recentre_yaw_std_rad`` wide, and
    # has to settle again from there.
    centred_m: float = 0.1
    centred_yaw_rad: float = math.radians(3.0)
    recentre_std_m: float = 0.05
    recentre_yaw_std_rad: float = math.radians(2.0)
    # Once the cloud holds one place (no rival, the scan fitting there) the tempering that
    # kept look-alike places alive has done its work; the beam product's exponent is raised
    # to this (annealing), so a cloud stretched along an aisle longer than the LiDAR's reach
    # tightens on what the scans do tell instead of staying as wide as the odometry leaves it.
    one_place_exponent: float = 0.25


class Body(Protocol):
    """What the localizer drives and reads: odometry, velocity commands and the LiDAR."""

    @property
    def odom_pose(self) -> FloatArray: ...

    def drive(self, v: float, w: float, dt: float) -> None: ...

    def scan(self) -> LaserScan: ...


@dataclass
class SimulatedBody:
    """A simulated base and LiDAR as a Body (the scan is taken at the true pose)."""

    base: SimulatedBase
    lidar: Lidar
    rng: np.random.Generator

    @property
    def odom_pose(self) -> FloatArray:
        return self.base.odom_pose

    def drive(self, v: float, w: float, dt: float) -> None:
        self.base.step(v, w, dt)

    def scan(self) -> LaserScan:
        return self.lidar.scan(self.base.true_pose, self.rng)


@dataclass(frozen=True)
class LocalizationOutcome:
    localized: bool
    estimate: PoseEstimate | None  # None unless localized: a spread cloud has no pose
    updates: int
    distance_m: float
    candidates: int  # clusters holding at least mode_share of the weight at the end
    message: str  # for a person


def scan_fit(pf: ParticleFilter, pose: FloatArray, scan: LaserScan, within_m: float) -> float:
    """Share of the usable beams that end within ``within_m`` of a mapped obstacle when the
    scan is laid down at ``pose`` (1.0 with no usable beam: nothing contradicts it)."""
    ranges, angles = pf.usable_beams(scan)
    if ranges.size == 0:
        return 1.0
    distances = pf.field.endpoint_distances(pose, ranges, angles)
    return float(np.mean(distances < within_m))


def candidate_places(pf: ParticleFilter, min_share: float) -> int:
    """How many clusters of the cloud hold at least ``min_share`` of its weight."""
    weights = np.exp(pf.log_weights - pf.log_weights.max())
    labels = cluster_labels(histogram_bins(pf.particles, pf.params), pf.params)
    totals = np.bincount(labels, weights=weights)
    return int(np.count_nonzero(totals >= min_share * totals.sum()))


def is_gathered(pf: ParticleFilter, params: ExploreParams) -> bool:
    """The cloud is one tight cluster (the spread part of the convergence test)."""
    est = pf.estimate
    if est is None or est.cluster_weight < params.converged_share:
        return False
    if est.position_std_m > params.converged_std_m:
        return False
    return math.sqrt(max(0.0, float(est.covariance[2, 2]))) <= params.converged_yaw_std_rad


def is_centred(estimate: FloatArray, place: FloatArray, params: ExploreParams) -> bool:
    """Whether the cloud's mean stands where the scan fits (``place``, scan-matched)."""
    off_m = math.hypot(float(place[0] - estimate[0]), float(place[1] - estimate[1]))
    off_yaw = abs(float(angle_diff(float(place[2]), float(estimate[2]))))
    return off_m <= params.centred_m and off_yaw <= params.centred_yaw_rad


def is_converged(pf: ParticleFilter, scan: LaserScan, params: ExploreParams) -> bool:
    """The convergence test of the module docstring, for one update."""
    if not is_gathered(pf, params):
        return False
    assert pf.estimate is not None
    place = refine(pf, pf.estimate.pose, scan)
    if not is_centred(pf.estimate.pose, place, params):
        return False
    return beam_fit(pf, place, scan, params.fit_distance_m) >= params.converged_fit


def clear_strips(
    scan: LaserScan, headings: FloatArray, length_m: float, half_width_m: float
) -> np.ndarray:
    """For each robot-frame heading, whether no return lies in the strip ``half_width_m``
    either side of it from just behind the robot's centre to ``length_m`` ahead."""
    hit = scan.ranges < scan.range_max
    px = scan.ranges[hit] * np.cos(scan.angles[hit])
    py = scan.ranges[hit] * np.sin(scan.angles[hit])
    c, s = np.cos(headings)[:, None], np.sin(headings)[:, None]
    along = c * px + s * py
    across = -s * px + c * py
    inside = (along > -half_width_m) & (along < length_m) & (np.abs(across) < half_width_m)
    return np.asarray(~inside.any(axis=1))


def free_headings(scan: LaserScan, params: ExploreParams, leg_m: float) -> FloatArray:
    """Robot-frame headings along which a leg of ``leg_m`` stays clear of every return
    (the swept strip is the robot's width plus ``clearance_m`` each side, and
    ``clearance_m`` further than the leg)."""
    candidates = np.linspace(-math.pi, math.pi, params.headings, endpoint=False)
    reach = leg_m + params.robot_radius_m + params.clearance_m
    half_width = params.robot_radius_m + params.clearance_m
    return np.asarray(candidates[clear_strips(scan, candidates, reach, half_width)])


@dataclass
class ActiveLocalizer:
    """Runs the turn-then-explore loop on a filter and a body."""

    pf: ParticleFilter
    body: Body
    params: ExploreParams = field(default_factory=ExploreParams)
    updates: int = field(init=False, default=0)
    distance_m: float = field(init=False, default=0.0)
    respreads: int = field(init=False, default=0)
    recentres: int = field(init=False, default=0)
    _settled: int = field(init=False, default=0)
    _misfit: int = field(init=False, default=0)
    _one_place: bool = field(init=False, default=False)
    _tempered_params: AmclParams | None = field(init=False, default=None)
    _last_scan: LaserScan | None = field(init=False, default=None)
    _visited: list[FloatArray] = field(init=False, default_factory=list)
    rivals: RivalPlaces = field(init=False, default_factory=RivalPlaces)

    def run(self, *, start_global: bool = True) -> LocalizationOutcome:
        tempered = self._tempered_params = self.pf.params
        try:
            return self._run(start_global)
        finally:  # the caller's filter tracks on with its own parameters
            self.pf.params = tempered

    def _run(self, start_global: bool) -> LocalizationOutcome:
        if start_global:
            self.pf.global_localization(self.body.scan(), self.params.oversample)
        self._visited = [self.body.odom_pose[:2].copy()]
        if self._update(force=True) or self._turn(self.params.spin_rad):
            return self._outcome(True)
        while self.updates < self.params.max_updates:
            assert self._last_scan is not None
            leg = self._pick_leg(self._last_scan)
            if leg is None:  # boxed in: turn a quarter and look again
                done = self._turn(math.pi / 2)
            else:
                done = self._turn(leg[0]) or self._drive(leg[1])
            if done:
                return self._outcome(True)
        return self._outcome(False)

    # -- motion ---------------------------------------------------------------------------
    def _turn(self, angle: float) -> bool:
        p = self.params
        turned = 0.0
        while abs(turned) < abs(angle) and self.updates < p.max_updates:
            step = math.copysign(min(p.turn_rate_rps * p.dt_s, abs(angle) - abs(turned)), angle)
            self.body.drive(0.0, step / p.dt_s, p.dt_s)
            turned += step
            if self._update():
                return True
        return False

    def _drive(self, length: float) -> bool:
        p = self.params
        driven = 0.0
        while driven < length and self.updates < p.max_updates:
            step = min(p.speed_mps * p.dt_s, length - driven)
            self.body.drive(step / p.dt_s, 0.0, p.dt_s)
            driven += step
            self.distance_m += step
            self._visited.append(self.body.odom_pose[:2].copy())
            if self._update():
                return True
            if self._last_scan is not None and not self._ahead_clear(self._last_scan):
                break
        return False

    def _ahead_clear(self, scan: LaserScan) -> bool:
        """Nothing new within the robot's radius plus half the clearance straight ahead."""
        p = self.params
        reach = p.robot_radius_m + p.clearance_m / 2 + p.speed_mps * p.dt_s
        ahead = clear_strips(scan, np.zeros(1), reach, p.robot_radius_m + p.clearance_m / 2)
        return bool(ahead[0])

    def _pick_leg(self, scan: LaserScan) -> tuple[float, float] | None:
        """(heading relative to the robot, length) of the next leg: the longest that fits
        (``leg_m``, halved down to ``shortest_leg_m``), towards the free heading whose end
        lies furthest from every place visited so far, in the odometry frame."""
        p = self.params
        length = p.leg_m
        while length >= p.shortest_leg_m:
            options = free_headings(scan, p, length)
            if options.size:
                break
            length /= 2
        else:
            return None
        odom = self.body.odom_pose
        ends = odom[:2] + length * np.column_stack(
            [np.cos(odom[2] + options), np.sin(odom[2] + options)]
        )
        visited = np.array(self._visited)
        gaps = np.hypot(ends[:, 0:1] - visited[None, :, 0], ends[:, 1:2] - visited[None, :, 1]).min(
            axis=1
        )
        return float(options[int(np.argmax(gaps))]), length

    # -- filter ---------------------------------------------------------------------------
    def _update(self, *, force: bool = False) -> bool:
        """Update the filter if the body moved enough; True once the cloud has converged."""
        odom = self.body.odom_pose
        if not (force or self.pf.needs_update(odom)):
            return False
        scan = self.body.scan()
        tempered = self._tempered_params or self.pf.params
        exponent = max(tempered.beam_product_exponent, self.params.one_place_exponent)
        self.pf.params = (
            replace(tempered, beam_product_exponent=exponent) if self._one_place else tempered
        )
        self.pf.update(odom, scan, force=True)
        self.updates += 1
        self._last_scan = scan
        for place in self.rivals.observe(self.pf, odom, scan):
            self.pf.drop(self.rivals.near(self.pf.particles, place))
        gathered = is_gathered(self.pf, self.params)
        est = self.pf.estimate
        assert est is not None
        place = refine(self.pf, est.pose, scan)
        fits = beam_fit(self.pf, place, scan, self.params.fit_distance_m)
        fits_well = fits >= self.params.converged_fit
        unrivalled = self.rivals.open == 0
        centred = is_centred(est.pose, place, self.params)
        if gathered and fits_well and unrivalled and not centred:
            p = self.params
            self.pf.initialize(
                place, (p.recentre_std_m**2, p.recentre_std_m**2, p.recentre_yaw_std_rad**2)
            )
            self.recentres += 1
        good = gathered and fits_well and unrivalled and centred
        self._one_place = (
            est.cluster_weight >= self.params.converged_share and fits_well and unrivalled
        )
        self._settled = self._settled + 1 if good else 0
        self._misfit = self._misfit + 1 if gathered and not fits_well else 0
        if self._misfit >= self.params.respread_after_updates:
            self.pf.params = self._tempered_params or self.pf.params
            self.pf.global_localization(scan, self.params.oversample)
            self.respreads += 1
            self._misfit = 0
            self.rivals = RivalPlaces(min_share=self.params.mode_share)
            self._one_place = False
        return self._settled >= self.params.settle_updates

    def _outcome(self, localized: bool) -> LocalizationOutcome:
        places = 1 + self.rivals.open
        if localized:
            est = self.pf.estimate
            assert est is not None
            message = (
                f"localized at ({est.x:.2f}, {est.y:.2f}) after {self.updates} updates and "
                f"{self.distance_m:.1f} m of driving"
            )
            return LocalizationOutcome(True, est, self.updates, self.distance_m, places, message)
        spread = (
            f"the estimate is still split between {places} places"
            if places > 1
            else "the particle cloud has not gathered into one tight cluster that fits the scan"
        )
        message = (
            f"not localized after {self.updates} updates and {self.distance_m:.1f} m of "
            f"driving: {spread}"
        )
        return LocalizationOutcome(False, None, self.updates, self.distance_m, places, message)


@dataclass
class LostWatch:
    """Says when a tracking filter has lost the robot: the scan has stopped fitting the map
    at the estimate (fewer than ``min_fit`` of the beams end within ``fit_distance_m`` of a
    mapped obstacle) for ``after_updates`` updates in a row, or augmented MCL's
    w_fast / w_slow signal (ParticleFilter.localization_lost). Returns of people and boxes
    the map lacks lower the fit a little; a kidnap or a wrong cluster lowers it a lot."""

    min_fit: float = 0.75
    fit_distance_m: float = 0.1
    after_updates: int = 3
    _poor: int = field(init=False, default=0)

    def lost(self, pf: ParticleFilter, scan: LaserScan) -> bool:
        est = pf.estimate
        if est is None:
            return True
        poor = scan_fit(pf, refine(pf, est.pose, scan), scan, self.fit_distance_m) < self.min_fit
        self._poor = self._poor + 1 if poor else 0
        return self._poor >= self.after_updates or pf.localization_lost
