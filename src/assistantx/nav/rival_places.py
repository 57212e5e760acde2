"""Places the particle cloud once held besides its estimate, followed until the scans rule
them out.

A particle filter keeps a look-alike place only as long as chance leaves particles there:
with two places that fit every scan equally, resampling thins one of them out within a few
dozen updates and the cloud looks converged, on a coin toss. So a cluster that held a share
of the weight is remembered as a rival: carried by the odometry like the robot, kept
aligned by a small scan-matching search (the cloud no longer corrects it), and scored
against the estimate by the beam model: each beam's measured range against the range the
map gives from that pose (ray cast), max-range readings included. The likelihood field the
filter uses cannot do this part: a beam that ends beyond a cupboard the map has, inside the
wall behind it, scores as well as one that stops at the cupboard; what tells a look-alike
apart is often such a thing missing. A rival is ruled out
when its total deficit reaches ``refute_nats`` (over all beams and updates), or merged
when it comes within ``same_place_m`` and ``same_place_rad`` of the estimate. While one is
open, the estimate is not a pose to declare.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import numpy as np

from assistantx.nav.amcl import ParticleFilter, cluster_labels, histogram_bins, weighted_pose_stats
from assistantx.nav.geometry import FloatArray, angle_diff, compose, relative
from assistantx.nav.lidar import LaserScan, cast_rays

# A 3 x 3 x 3 neighbourhood for the local search: 5 cm and about 1 degree either way.
_STEPS = np.array(
    list(itertools.product((-0.05, 0.0, 0.05), (-0.05, 0.0, 0.05), (-0.02, 0.0, 0.02)))
)


def cluster_poses(pf: ParticleFilter, min_share: float) -> list[tuple[FloatArray, float]]:
    """(mean pose, share of the weight) of each cluster holding at least ``min_share``,
    heaviest first."""
    weights = np.exp(pf.log_weights - pf.log_weights.max())
    labels = cluster_labels(histogram_bins(pf.particles, pf.params), pf.params)
    totals = np.bincount(labels, weights=weights)
    share = totals / totals.sum()
    out = []
    for label in np.argsort(-share):
        if share[label] < min_share:
            break
        members = labels == label
        mean, _ = weighted_pose_stats(pf.particles[members], weights[members])
        out.append((mean, float(share[label])))
    return out


@dataclass
class Rival:
    pose: FloatArray
    deficit: float = 0.0  # summed log-likelihood (nats) below the estimate's


@dataclass
class RivalPlaces:
    min_share: float = 0.05
    refute_nats: float = 10.0
    same_place_m: float = 0.5
    same_place_rad: float = math.radians(20)
    rivals: list[Rival] = field(default_factory=list)
    ruled_out: int = 0
    _odom: FloatArray | None = field(init=False, default=None)
    _estimate: FloatArray | None = field(init=False, default=None)

    @property
    def open(self) -> int:
        return len(self.rivals)

    def observe(self, pf: ParticleFilter, odom: FloatArray, scan: LaserScan) -> list[FloatArray]:
        """After a filter update: move, align and score the rivals, take in new ones, and
        return the places the scans have ruled out (a rival, or the estimate's own place
        when a rival beats it by ``refute_nats``): the caller drops their particles."""
        est = pf.estimate
        assert est is not None
        step = None if self._odom is None else relative(odom, self._odom)
        self._odom = np.asarray(odom, dtype=float).copy()
        if step is not None:
            for rival in self.rivals:
                rival.pose = compose(rival.pose, step)
            if self._estimate is not None:
                self._estimate = compose(self._estimate, step)
        here = est.pose
        # The place the estimate has just left, if it jumped, is a rival too.
        if self._estimate is not None and not self._same(self._estimate, here):
            self.rivals.append(Rival(self._estimate))
        self._estimate = here.copy()
        for pose, _share in cluster_poses(pf, self.min_share)[1:]:
            if not self._same(pose, here) and not any(
                self._same(pose, r.pose) for r in self.rivals
            ):
                self.rivals.append(Rival(pose))
        ranges, angles = pf.usable_beams(scan)
        if ranges.size == 0:
            return []
        beams = _beams(pf, scan)
        here = _align(pf, here, ranges, angles)
        best = _beam_score(pf, here, beams, scan.range_max)
        kept: list[Rival] = []
        out: list[FloatArray] = []
        for rival in self.rivals:
            rival.pose = _align(pf, rival.pose, ranges, angles)
            rival.deficit += best - _beam_score(pf, rival.pose, beams, scan.range_max)
            if self._same(rival.pose, here):
                continue
            if rival.deficit >= self.refute_nats:
                self.ruled_out += 1
                out.append(rival.pose)
                continue
            if rival.deficit <= -self.refute_nats:  # the estimate's place is the one ruled out
                self.ruled_out += 1
                out.append(here)
                self._estimate = None
                continue  # the rival's particles carry on; it is no longer a rival
            kept.append(rival)
        self.rivals = kept
        return out

    def near(self, poses: FloatArray, place: FloatArray) -> np.ndarray:
        """Which of ``poses`` (n, 3) lie at ``place`` (within the same-place bounds)."""
        return np.asarray(
            (np.hypot(poses[:, 0] - place[0], poses[:, 1] - place[1]) < self.same_place_m)
            & (np.abs(angle_diff(poses[:, 2], place[2])) < self.same_place_rad)
        )

    def _same(self, a: FloatArray, b: FloatArray) -> bool:
        return bool(
            math.hypot(a[0] - b[0], a[1] - b[1]) < self.same_place_m
            and abs(float(angle_diff(a[2], b[2]))) < self.same_place_rad
        )


def _align(
    pf: ParticleFilter, pose: FloatArray, ranges: FloatArray, angles: FloatArray
) -> FloatArray:
    """The pose of the small neighbourhood of ``pose`` that the scan fits best."""
    candidates = compose(np.broadcast_to(pose, _STEPS.shape), _STEPS)
    scores = pf.field.beam_log_likelihood(candidates, ranges, angles)
    return np.asarray(candidates[int(np.argmax(scores))])


def refine(pf: ParticleFilter, pose: FloatArray, scan: LaserScan, steps: int = 4) -> FloatArray:
    """``pose`` moved by up to ``steps`` small scan-matching steps (5 cm, 1 degree each) to
    where the scan fits best: the place the filter's estimate stands for, without the
    spread of a tempered cloud."""
    ranges, angles = pf.usable_beams(scan)
    if ranges.size == 0:
        return pose
    for _ in range(steps):
        pose = _align(pf, pose, ranges, angles)
    return pose


def beam_fit(pf: ParticleFilter, pose: FloatArray, scan: LaserScan, within_m: float) -> float:
    """Share of the beams (max-range readings included) whose range is within ``within_m``
    of the range the map gives from ``pose``: unlike the likelihood field, a beam that
    passes through something the map has there counts against the pose."""
    ranges, angles = _beams(pf, scan)
    expected = cast_rays(_walls(pf), pf.grid, pose, angles, scan.range_max)
    return float(np.mean(np.abs(ranges - expected) < within_m))


def _walls(pf: ParticleFilter) -> np.ndarray:
    grid = pf.grid
    return grid.obstacles | grid.unknown_rim if pf.params.unknown_rim_is_wall else grid.obstacles


def _beams(pf: ParticleFilter, scan: LaserScan) -> tuple[FloatArray, FloatArray]:
    """``max_beams`` evenly spaced beams of the scan, max-range readings kept."""
    step = max(1, scan.ranges.size // pf.params.max_beams)
    return scan.ranges[::step], scan.angles[::step]


def _beam_score(
    pf: ParticleFilter, pose: FloatArray, beams: tuple[FloatArray, FloatArray], max_range: float
) -> float:
    """Log-likelihood (summed over the beams) of the measured ranges given the map's ranges from
    ``pose``: a Gaussian of ``sigma_hit`` about the expected range, mixed with a uniform."""
    ranges, angles = beams
    p = pf.params
    expected = cast_rays(_walls(pf), pf.grid, pose, angles, max_range)
    hit = p.z_hit * np.exp(-((ranges - expected) ** 2) / (2 * p.sigma_hit**2))
    return float(np.sum(np.log(hit + p.z_rand / max_range)))
