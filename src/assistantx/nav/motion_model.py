"""The odometry motion model of a differential-drive base (nav2's DifferentialMotionModel,
Probabilistic Robotics table 5.6): an odometry step is split into rotate (rot1), translate
(trans), rotate (rot2), and each part gets Gaussian noise whose variance grows with the
motion::

    var(rot1)  = alpha1 * rot1^2 + alpha2 * trans^2
    var(trans) = alpha3 * trans^2 + alpha4 * (rot1^2 + rot2^2)
    var(rot2)  = alpha1 * rot2^2 + alpha2 * trans^2

alpha1 is rotation noise from rotation, alpha2 rotation from translation, alpha3 translation
from translation, alpha4 translation from rotation. As in nav2, a backwards step uses the
rotation to the nearer of forward/backward for the noise, so reversing is not a half turn.
The same function moves AMCL's particles and corrupts the simulated base's odometry.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from assistantx.nav.geometry import FloatArray, angle_diff, wrap_angle


@dataclass(frozen=True)
class OdometryNoise:
    alpha1: float = 0.2
    alpha2: float = 0.2
    alpha3: float = 0.2
    alpha4: float = 0.2


def odometry_deltas(odom_prev: FloatArray, odom_now: FloatArray) -> tuple[float, float, float]:
    """(rot1, trans, rot2) of the step between two odometry poses."""
    dx, dy = float(odom_now[0] - odom_prev[0]), float(odom_now[1] - odom_prev[1])
    trans = float(np.hypot(dx, dy))
    # Below 1 cm the direction of travel is noise; treat the step as a pure rotation.
    rot1 = float(angle_diff(np.arctan2(dy, dx), odom_prev[2])) if trans >= 0.01 else 0.0
    rot2 = float(angle_diff(angle_diff(odom_now[2], odom_prev[2]), rot1))
    return rot1, trans, rot2


def motion_model(
    poses: FloatArray,
    odom_prev: FloatArray,
    odom_now: FloatArray,
    noise: OdometryNoise,
    rng: np.random.Generator,
) -> FloatArray:
    """Sample new poses (n, 3) after the odometry moved from ``odom_prev`` to ``odom_now``."""
    rot1, trans, rot2 = odometry_deltas(odom_prev, odom_now)
    # Noise on the smaller of the forward/backward interpretations of each rotation.
    rot1_noise = min(abs(rot1), abs(float(angle_diff(rot1, np.pi))))
    rot2_noise = min(abs(rot2), abs(float(angle_diff(rot2, np.pi))))
    n = poses.shape[0]
    sd_rot1 = np.sqrt(noise.alpha1 * rot1_noise**2 + noise.alpha2 * trans**2)
    sd_trans = np.sqrt(noise.alpha3 * trans**2 + noise.alpha4 * (rot1_noise**2 + rot2_noise**2))
    sd_rot2 = np.sqrt(noise.alpha1 * rot2_noise**2 + noise.alpha2 * trans**2)
    z = rng.standard_normal((3, n))
    rot1_hat = rot1 - sd_rot1 * z[0]
    trans_hat = trans - sd_trans * z[1]
    rot2_hat = rot2 - sd_rot2 * z[2]
    heading = poses[:, 2] + rot1_hat
    out = np.empty_like(poses)
    out[:, 0] = poses[:, 0] + trans_hat * np.cos(heading)
    out[:, 1] = poses[:, 1] + trans_hat * np.sin(heading)
    out[:, 2] = wrap_angle(heading + rot2_hat)
    return out
