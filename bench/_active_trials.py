"""Global-localization and kidnapped-robot trials with the robot moving while it localizes
(assistantx.nav.active_localization), shared by robot_amcl_global.py (office) and
robot_real_maps.py (nav2's maps).

Global: the filter starts from a uniform cloud; the robot turns in place, then drives short
legs into free space it picks from its scan, until the cloud has converged (or
``ExploreParams.max_updates`` updates have passed: then it reports "not localized").
Kidnapped: the robot tracks along a route for 20 updates, is carried to another random spot
without the odometry noticing and drives on; when LostWatch says it is lost, it spreads the
cloud over the map and localizes as above.

A trial succeeds only when the robot declared itself localized, the declared estimate is
within POS_TOL_M and YAW_TOL of the TRUE pose, and it stays within them for the next
``CHECK_UPDATES`` updates of driving a route. A failure whose final estimate sees the map as
the true pose does is counted apart ("look-alike"), still as a failure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from _tours import TourWorld

from assistantx.nav.active_localization import (
    ActiveLocalizer,
    ExploreParams,
    LostWatch,
    SimulatedBody,
)
from assistantx.nav.amcl import AmclParams, ParticleFilter
from assistantx.nav.diff_drive import PurePursuit, SimulatedBase
from assistantx.nav.geometry import angle_diff
from assistantx.nav.lidar import Lidar

POS_TOL_M = 0.25
YAW_TOL = math.radians(10)
CHECK_UPDATES = 10  # after the declaration, the estimate must stay right this long
TRACK_UPDATES = 20  # before a kidnap
LOST_WITHIN = 60  # updates of driving after a kidnap for LostWatch to notice
# One filter for both trials: augmented MCL on (a cloud that settles on a wrong place is
# re-seeded), a tempered beam product (a spread cloud is not collapsed by one scan).
PARAMS = AmclParams(
    max_particles=20000,
    min_particles=500,
    recovery_alpha_slow=0.001,
    recovery_alpha_fast=0.1,
    beam_product_exponent=0.05,
    resample_min_neff_ratio=0.5,
)
EXPLORE = ExploreParams()


class TrialWorld(TourWorld):
    lidar: Lidar


@dataclass(frozen=True)
class Trial:
    success: bool
    localized: bool  # the robot declared a pose
    updates: int  # filter updates from the start (global) or the kidnap (kidnapped)
    distance_m: float
    candidates: int
    final_pose: np.ndarray | None  # the estimate at the end (for the look-alike check)
    true_pose: np.ndarray


def within(pf: ParticleFilter, true_pose: np.ndarray) -> bool:
    est = pf.estimate
    assert est is not None
    err = math.hypot(est.x - true_pose[0], est.y - true_pose[1])
    return err < POS_TOL_M and abs(float(angle_diff(est.yaw, true_pose[2]))) < YAW_TOL


def drive_route(
    pf: ParticleFilter,
    base: SimulatedBase,
    lidar: Lidar,
    route: PurePursuit,
    updates: int,
    rng: np.random.Generator,
    watch: LostWatch | None = None,
) -> tuple[list[bool], bool]:
    """Drive (steered by the true pose, as if tele-operated) and update; per update whether
    the estimate is within tolerance; and whether ``watch`` said lost (driving stops)."""
    ok: list[bool] = []
    while len(ok) < updates:
        v, w, done = route.command(base.true_pose)
        if done:
            break
        base.step(v, w, 0.1)
        scan = lidar.scan(base.true_pose, rng)
        if pf.update(base.odom_pose, scan):
            ok.append(within(pf, base.true_pose))
            if watch is not None and watch.lost(pf, scan):
                return ok, True
    return ok, False


def _confirm(
    world: TrialWorld,
    pf: ParticleFilter,
    base: SimulatedBase,
    rng: np.random.Generator,
    localized: bool,
) -> bool:
    if not (localized and within(pf, base.true_pose)):
        return False
    ok, _ = drive_route(pf, base, world.lidar, world.route(base.true_pose, rng), CHECK_UPDATES, rng)
    return all(ok)


def global_trial(world: TrialWorld, seed: int) -> Trial:
    rng = np.random.default_rng(seed)
    start = world.random_pose(rng)
    base = SimulatedBase(start, rng)
    pf = ParticleFilter(world.grid, PARAMS, rng)
    outcome = ActiveLocalizer(pf, SimulatedBody(base, world.lidar, rng), EXPLORE).run()
    final = pf.estimate.pose if pf.estimate is not None else None
    truth = base.true_pose.copy()
    success = _confirm(world, pf, base, rng, outcome.localized)
    return Trial(
        success,
        outcome.localized,
        outcome.updates,
        outcome.distance_m,
        outcome.candidates,
        final,
        truth,
    )


def kidnap_trial(world: TrialWorld, seed: int) -> Trial:
    rng = np.random.default_rng(seed)
    start = world.random_pose(rng)
    base = SimulatedBase(start, rng)
    pf = ParticleFilter(world.grid, PARAMS, rng)
    pf.initialize(start)
    drive_route(pf, base, world.lidar, world.route(start, rng), TRACK_UPDATES, rng)
    base.teleport(world.random_pose(rng))
    watch = LostWatch()
    seen, lost = drive_route(
        pf, base, world.lidar, world.route(base.true_pose, rng), LOST_WITHIN, rng, watch
    )
    if not lost:  # never noticed: it believes its estimate, right or wrong
        final = pf.estimate.pose if pf.estimate is not None else None
        truth = base.true_pose.copy()
        success = _confirm(world, pf, base, rng, True)
        return Trial(success, True, len(seen), 0.0, 1, final, truth)
    outcome = ActiveLocalizer(pf, SimulatedBody(base, world.lidar, rng), EXPLORE).run()
    final = pf.estimate.pose if pf.estimate is not None else None
    truth = base.true_pose.copy()
    success = _confirm(world, pf, base, rng, outcome.localized)
    return Trial(
        success,
        outcome.localized,
        len(seen) + outcome.updates,
        outcome.distance_m,
        outcome.candidates,
        final,
        truth,
    )
