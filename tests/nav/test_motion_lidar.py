"""Odometry noise statistics, the differential drive, and LiDAR ray casting."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from assistantx.nav.diff_drive import (
    DriveParams,
    PurePursuit,
    SimulatedBase,
    integrate,
)
from assistantx.nav.geometry import angle_diff, compose, relative, wrap_angle
from assistantx.nav.lidar import Lidar, LidarParams, beam_angles, cast_rays
from assistantx.nav.motion_model import OdometryNoise, motion_model, odometry_deltas
from assistantx.nav.occupancy_map import OCCUPIED, OccupancyMap

N = 40_000


def test_noise_free_motion_is_exact() -> None:
    rng = np.random.default_rng(0)
    start = np.array([[1.0, 2.0, 0.3]])
    moved = motion_model(
        start, np.array([0.0, 0.0, 0.0]), np.array([1.0, 1.0, 0.5]), OdometryNoise(0, 0, 0, 0), rng
    )
    expected = compose(start[0], np.array([1.0, 1.0, 0.5]))
    np.testing.assert_allclose(moved[0], expected, atol=1e-12)


def test_translation_noise_matches_the_alphas() -> None:
    rng = np.random.default_rng(1)
    noise = OdometryNoise(alpha1=0.1, alpha2=0.05, alpha3=0.2, alpha4=0.3)
    poses = motion_model(np.zeros((N, 3)), np.zeros(3), np.array([2.0, 0.0, 0.0]), noise, rng)
    trans = np.hypot(poses[:, 0], poses[:, 1])
    # var(trans) = alpha3 * 4 -> sd 0.894; var(rot1) = alpha2 * 4 -> sd 0.447
    assert trans.mean() == pytest.approx(2.0, abs=0.02)
    assert trans.std() == pytest.approx(math.sqrt(0.2 * 4), rel=0.03)
    heading = np.arctan2(poses[:, 1], poses[:, 0])  # rot1_hat, where trans_hat > 0
    forward = (trans > 0.3) & (poses[:, 0] > 0)
    assert heading[forward].std() == pytest.approx(math.sqrt(0.05 * 4), rel=0.06)
    # Final heading: rot1 + rot2 noise, each var alpha2 * trans^2.
    assert poses[:, 2].std() == pytest.approx(math.sqrt(2 * 0.05 * 4), rel=0.05)


def test_rotation_noise_matches_the_alphas() -> None:
    rng = np.random.default_rng(2)
    noise = OdometryNoise(alpha1=0.2, alpha2=0.0, alpha3=0.0, alpha4=0.1)
    poses = motion_model(np.zeros((N, 3)), np.zeros(3), np.array([0.0, 0.0, 1.0]), noise, rng)
    # Pure rotation: rot1 = 0, rot2 = 1 rad, var(rot2) = alpha1 -> sd 0.447.
    assert poses[:, 2].mean() == pytest.approx(1.0, abs=0.01)
    assert poses[:, 2].std() == pytest.approx(math.sqrt(0.2), rel=0.03)
    # Translation from rotation: var = alpha4 * rot2^2 -> sd 0.316 along the start heading.
    assert poses[:, 0].std() == pytest.approx(math.sqrt(0.1), rel=0.03)


def test_reversing_is_not_a_half_turn() -> None:
    rot1, trans, rot2 = odometry_deltas(np.zeros(3), np.array([-0.5, 0.0, 0.0]))
    assert (abs(rot1), trans, abs(rot2)) == pytest.approx((math.pi, 0.5, math.pi))
    rng = np.random.default_rng(3)
    poses = motion_model(
        np.zeros((N, 3)), np.zeros(3), np.array([-0.5, 0.0, 0.0]), OdometryNoise(0.2, 0, 0, 0), rng
    )
    # Noise uses the rotation to the nearer of forward/backward (0), so it stays tiny.
    assert np.abs(wrap_angle(poses[:, 2])).max() < 1e-9


def test_geometry_round_trip() -> None:
    a, b = np.array([1.0, -2.0, 3.0]), np.array([0.5, 0.2, -2.9])
    np.testing.assert_allclose(compose(b, relative(a, b)), a, atol=1e-12)
    assert float(angle_diff(3.1, -3.1)) == pytest.approx(6.2 - 2 * math.pi)


def test_integrate_arcs_and_lines() -> None:
    straight = integrate(np.array([0.0, 0.0, math.pi / 2]), 0.5, 0.0, 2.0)
    np.testing.assert_allclose(straight, [0.0, 1.0, math.pi / 2], atol=1e-12)
    quarter = integrate(np.zeros(3), math.pi / 2, math.pi / 2, 1.0)  # radius 1, quarter turn
    np.testing.assert_allclose(quarter, [1.0, 1.0, math.pi / 2], atol=1e-12)


def test_pure_pursuit_reaches_the_goal_and_heading() -> None:
    rng = np.random.default_rng(4)
    base = SimulatedBase(np.array([0.0, 0.0, 0.0]), rng)
    path = np.column_stack([np.linspace(0, 3, 61), np.r_[np.zeros(30), np.linspace(0, 1.5, 31)]])
    controller = PurePursuit(path, math.pi / 2, DriveParams())
    for _ in range(500):
        v, w, done = controller.command(base.true_pose)
        if done:
            break
        base.step(v, w, 0.1)
    assert done
    assert math.hypot(base.true_pose[0] - 3, base.true_pose[1] - 1.5) <= 0.05
    assert abs(float(angle_diff(base.true_pose[2], math.pi / 2))) <= 0.05
    assert base.odometer_m == pytest.approx(3.4, abs=0.3)
    # The odometry drifted, but only a little (alphas 0.005).
    assert 0 < math.hypot(*(base.odom_pose - base.true_pose)[:2]) < 0.2


def test_pure_pursuit_drives_a_route_that_ends_where_it_starts() -> None:
    # A 2 m x 1 m loop, back to its first point: the goal is where the robot stands, yet
    # the route is to be driven round, not declared done at once.
    rng = np.random.default_rng(5)
    base = SimulatedBase(np.array([0.0, 0.0, 0.0]), rng)
    corners = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0], [0.0, 0.0]])
    path = np.vstack(
        [np.linspace(a, b, 41)[:-1] for a, b in itertools.pairwise(corners)] + [corners[-1:]]
    )
    controller = PurePursuit(path, None, DriveParams())
    farthest = 0.0
    for _ in range(1000):
        v, w, done = controller.command(base.true_pose)
        if done:
            break
        base.step(v, w, 0.1)
        farthest = max(farthest, float(base.true_pose[0]))
    assert done
    assert farthest > 1.7  # it went round
    assert base.odometer_m == pytest.approx(6.0, abs=0.6)
    assert math.hypot(*base.true_pose[:2]) <= 0.05


def _room() -> OccupancyMap:
    data = np.zeros((80, 100), dtype=np.int8)  # 5 m x 4 m at 5 cm
    data[0, :] = data[-1, :] = data[:, 0] = data[:, -1] = OCCUPIED
    return OccupancyMap(data, 0.05)


def test_ray_casting_distances_to_the_walls() -> None:
    grid = _room()
    pose = np.array([2.0, 1.5, 0.0])
    angles = np.array([0.0, math.pi / 2, math.pi, -math.pi / 2, math.atan2(2.45, 2.95)])
    ranges = cast_rays(grid.occupied, grid, pose, angles, 10.0)
    # Walls' inner faces at x = 0.05, 4.95 and y = 0.05, 3.95.
    expected = [2.95, 2.45, 1.95, 1.45, math.hypot(2.95, 2.45)]
    np.testing.assert_allclose(ranges, expected, atol=0.0126)
    short = cast_rays(grid.occupied, grid, pose, np.array([0.0]), 1.0)
    assert short.tolist() == [1.0]  # no return within max range


def test_scan_noise_and_beam_layout() -> None:
    lidar = Lidar(_room(), LidarParams(beams=4, range_noise_std_m=0.02))
    assert beam_angles(lidar.params).tolist() == pytest.approx(
        [-math.pi, -math.pi / 2, 0, math.pi / 2]
    )
    rng = np.random.default_rng(5)
    pose = np.array([2.0, 1.5, 0.0])
    scans = np.array([lidar.scan(pose, rng).ranges for _ in range(3000)])
    assert scans[:, 2].mean() == pytest.approx(2.95, abs=0.015)
    assert scans[:, 2].std() == pytest.approx(0.02, rel=0.08)
