"""AMCL pieces (resampling, KLD bound, clusters, circular statistics) and the whole filter
converging on a small seeded map."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assistantx.nav.amcl import (
    AmclParams,
    ParticleFilter,
    cluster_labels,
    histogram_bins,
    kld_prefix_length,
    kld_sample_count,
    low_variance_resample,
    weighted_pose_stats,
)
from assistantx.nav.diff_drive import SimulatedBase
from assistantx.nav.geometry import angle_diff
from assistantx.nav.lidar import Lidar, LidarParams
from assistantx.nav.occupancy_map import OCCUPIED, OccupancyMap

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow


def test_low_variance_resample_counts_are_proportional() -> None:
    rng = np.random.default_rng(0)
    weights = rng.random(50) ** 3
    n = 1000
    idx = low_variance_resample(weights, n, rng)
    counts = np.bincount(idx, minlength=50)
    expected = n * weights / weights.sum()
    # Systematic resampling: each count is the expectation rounded up or down.
    assert (np.abs(counts - expected) < 1.0 + 1e-9).all()
    assert counts.sum() == n
    assert np.all(np.diff(idx) >= 0)  # sorted, one pass
    zero = low_variance_resample(np.array([0.0, 1.0, 0.0]), 10, rng)
    assert set(zero.tolist()) == {1}


def test_kld_sample_count() -> None:
    # Fox (2003): k = 100 bins, epsilon 0.05, z 0.99 (as amcl uses it).
    k = 100
    a = 2 / (9 * (k - 1))
    expected = (k - 1) / (2 * 0.05) * (1 - a + math.sqrt(a) * 0.99) ** 3
    assert float(kld_sample_count(k, 0.05, 0.99)) == pytest.approx(expected)
    counts = kld_sample_count(np.arange(1, 500), 0.05, 0.99)
    assert np.all(np.diff(counts) > 0)
    assert float(kld_sample_count(1, 0.05, 0.99)) == 1.0


def test_kld_prefix_stops_early_when_concentrated() -> None:
    params = AmclParams(min_particles=100, max_particles=5000)
    rng = np.random.default_rng(1)
    tight = np.column_stack(
        [rng.normal(5, 0.05, 5000), rng.normal(5, 0.05, 5000), rng.normal(0, 0.02, 5000)]
    )
    spread = np.column_stack(
        [rng.uniform(0, 40, 5000), rng.uniform(0, 25, 5000), rng.uniform(-3, 3, 5000)]
    )
    # A few bins (the cloud straddles bin edges): the KLD bound is met near min_particles.
    assert kld_prefix_length(histogram_bins(tight, params), params) <= 120
    assert kld_prefix_length(histogram_bins(spread, params), params) == 5000


def test_clusters_join_across_the_heading_wrap() -> None:
    params = AmclParams()
    poses = np.array(
        [
            [1.0, 1.0, math.pi - 0.01],
            [1.0, 1.0, -math.pi + 0.01],  # same heading, across the wrap
            [1.3, 1.2, math.pi - 0.1],
            [8.0, 8.0, 0.0],  # far away: its own cluster
        ]
    )
    labels = cluster_labels(histogram_bins(poses, params), params)
    assert labels[0] == labels[1] == labels[2] != labels[3]


def test_circular_mean_and_variance() -> None:
    poses = np.array([[0.0, 0.0, math.pi - 0.1], [2.0, 0.0, -math.pi + 0.1]])
    mean, cov = weighted_pose_stats(poses, np.array([1.0, 1.0]))
    assert abs(float(angle_diff(mean[2], math.pi))) < 1e-9  # not 0, as a linear mean gives
    assert mean[0] == pytest.approx(1.0)
    assert cov[0, 0] == pytest.approx(1.0)
    # Resultant length cos(0.1): circular variance -2 ln R = 0.01 rad^2 (about sigma^2).
    assert cov[2, 2] == pytest.approx(-2 * math.log(math.cos(0.1)))


def _small_world() -> OccupancyMap:
    """A 10 x 7 m room with irregular furniture, 5 cm cells."""
    data = np.zeros((140, 200), dtype=np.int8)
    data[:3, :] = data[-3:, :] = data[:, :3] = data[:, -3:] = OCCUPIED
    data[30:50, 40:60] = OCCUPIED
    data[90:96, 100:170] = OCCUPIED
    data[20:70, 140:146] = OCCUPIED
    data[110:140, 30:36] = OCCUPIED
    return OccupancyMap(data, 0.05)


def _drive(
    pf: ParticleFilter, base: SimulatedBase, lidar: Lidar, steps: int, rng: np.random.Generator
) -> list[float]:
    errors = []
    for _ in range(steps):
        base.step(0.3, 0.3, 0.1)  # a 1 m circle, clear of the furniture
        if pf.update(base.odom_pose, lidar.scan(base.true_pose, rng)):
            est = pf.estimate
            assert est is not None
            errors.append(math.hypot(est.x - base.true_pose[0], est.y - base.true_pose[1]))
    return errors


def test_tracking_converges_from_an_offset_start() -> None:
    rng = np.random.default_rng(7)
    world = _small_world()
    lidar = Lidar(world, LidarParams(beams=120, max_range_m=8.0))
    base = SimulatedBase(np.array([4.5, 2.0, 0.0]), rng)
    pf = ParticleFilter(world, AmclParams(max_particles=1000, min_particles=200), rng)
    pf.initialize(np.array([4.8, 1.7, 0.15]))  # 42 cm and 9 degrees off
    assert pf.estimate is not None
    assert math.hypot(pf.estimate.x - 4.5, pf.estimate.y - 2.0) > 0.3
    errors = _drive(pf, base, lidar, 120, rng)
    assert len(errors) >= 10
    assert max(errors[-5:]) < 0.08
    now = pf.pose_from_odometry(base.odom_pose)  # the estimate carried to this instant
    assert abs(float(angle_diff(now[2], base.true_pose[2]))) < math.radians(3)
    assert pf.estimate.position_std_m < 0.15
    assert len(pf.particles) < 1000  # KLD shrank the cloud once it converged


def test_global_localization_on_the_small_map() -> None:
    # One seeded trial; bench/robot_amcl.py measures the success rate over many.
    rng = np.random.default_rng(1)
    world = _small_world()
    lidar = Lidar(world, LidarParams(beams=120, max_range_m=8.0))
    base = SimulatedBase(np.array([4.5, 2.0, 0.0]), rng)
    pf = ParticleFilter(world, AmclParams(max_particles=8000, min_particles=500), rng)
    pf.global_localization()
    assert pf.estimate is not None
    assert pf.estimate.position_std_m > 1.0
    errors = _drive(pf, base, lidar, 150, rng)
    assert max(errors[-3:]) < 0.1


def test_same_seed_same_result_and_weights_kept_between_resamples() -> None:
    world = _small_world()
    results = []
    for _ in range(2):
        rng = np.random.default_rng(3)
        lidar = Lidar(world, LidarParams(beams=90, max_range_m=8.0))
        base = SimulatedBase(np.array([4.5, 2.0, 0.0]), rng)
        pf = ParticleFilter(
            world, AmclParams(max_particles=500, min_particles=100, resample_interval=3), rng
        )
        pf.initialize(base.true_pose)
        pf.update(base.odom_pose, lidar.scan(base.true_pose, rng))
        # After one update without resampling the weights are not uniform.
        assert np.ptp(pf.log_weights) > 1.0
        assert len(pf.particles) == 500
        _drive(pf, base, lidar, 40, rng)
        results.append(pf.particles.copy())
    np.testing.assert_array_equal(results[0], results[1])


def _recovering_filter(
    rng: np.random.Generator,
) -> tuple[ParticleFilter, SimulatedBase, Lidar]:
    """A filter with recovery on, started at the true pose of a base in the small world."""
    world = _small_world()
    lidar = Lidar(world, LidarParams(beams=120, max_range_m=8.0))
    base = SimulatedBase(np.array([4.5, 2.0, 0.0]), rng)
    params = AmclParams(
        max_particles=3000, min_particles=300, recovery_alpha_slow=0.001, recovery_alpha_fast=0.1
    )
    pf = ParticleFilter(world, params, rng)
    pf.initialize(base.true_pose)
    return pf, base, lidar


def test_recovery_injects_random_poses_after_a_kidnap() -> None:
    rng = np.random.default_rng(5)
    pf, base, lidar = _recovering_filter(rng)
    _drive(pf, base, lidar, 40, rng)
    assert pf.random_pose_probability < 0.2
    base.teleport(np.array([4.0, 4.5, math.pi]))
    errors = _drive(pf, base, lidar, 300, rng)
    assert max(errors[-3:]) < 0.1


def test_params_validation() -> None:
    with pytest.raises(ValueError, match="min_particles"):
        AmclParams(min_particles=10, max_particles=5)
    with pytest.raises(ValueError, match="resample_interval"):
        AmclParams(resample_interval=0)


def test_beam_product_exponent_tempers_the_weights() -> None:
    world = _small_world()
    rng = np.random.default_rng(9)
    scan = Lidar(world, LidarParams(beams=90, max_range_m=8.0)).scan(np.array([4.5, 2.0, 0.0]), rng)
    spreads = []
    for exponent in (1.0, 0.25):
        pf = ParticleFilter(
            world,
            AmclParams(max_particles=300, min_particles=300, beam_product_exponent=exponent),
            np.random.default_rng(1),
        )
        pf.initialize(np.array([4.5, 2.0, 0.0]))
        pf.sensor_update(scan)
        spreads.append(float(np.ptp(pf.log_weights)))
    assert spreads[1] == pytest.approx(spreads[0] * 0.25)


def test_localization_lost_signal_rises_after_a_kidnap_and_clears_on_recovery() -> None:
    rng = np.random.default_rng(5)
    pf, base, lidar = _recovering_filter(rng)
    lost_while_tracking = []
    for _ in range(40):
        _drive(pf, base, lidar, 1, rng)
        lost_while_tracking.append(pf.localization_lost)
    assert not any(lost_while_tracking)
    base.teleport(np.array([4.0, 4.5, math.pi]))
    lost_after = []
    for _ in range(60):
        _drive(pf, base, lidar, 1, rng)
        lost_after.append(pf.localization_lost)
    assert any(lost_after[:30])
    _drive(pf, base, lidar, 240, rng)
    assert not pf.localization_lost
    # Without recovery (nav2's defaults, alphas 0) there is no signal to give.
    quiet = ParticleFilter(_small_world(), AmclParams(max_particles=500, min_particles=100), rng)
    quiet.initialize(np.array([1.0, 1.0, 0.0]))
    _drive(quiet, base, lidar, 20, rng)
    assert not quiet.localization_lost
