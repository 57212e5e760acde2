"""Planar poses as (x m, y m, yaw rad) arrays, and angle arithmetic that wraps to (-pi, pi]."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]


def wrap_angle(angle: npt.ArrayLike) -> FloatArray:
    """Wrap radians to (-pi, pi]."""
    a = np.asarray(angle, dtype=float)
    return np.asarray(np.pi - np.mod(np.pi - a, 2 * np.pi))


def angle_diff(a: npt.ArrayLike, b: npt.ArrayLike) -> FloatArray:
    """Smallest signed angle a - b, in (-pi, pi]."""
    return wrap_angle(np.asarray(a, dtype=float) - np.asarray(b, dtype=float))


def compose(pose: FloatArray, delta: FloatArray) -> FloatArray:
    """pose ⊕ delta: apply ``delta`` (expressed in the frame of ``pose``); broadcasts over rows."""
    c, s = np.cos(pose[..., 2]), np.sin(pose[..., 2])
    x = pose[..., 0] + c * delta[..., 0] - s * delta[..., 1]
    y = pose[..., 1] + s * delta[..., 0] + c * delta[..., 1]
    return np.stack([x, y, wrap_angle(pose[..., 2] + delta[..., 2])], axis=-1)


def relative(a: FloatArray, b: FloatArray) -> FloatArray:
    """a ⊖ b: the pose of ``a`` in the frame of ``b`` (so compose(b, relative(a, b)) == a)."""
    c, s = np.cos(b[..., 2]), np.sin(b[..., 2])
    dx, dy = a[..., 0] - b[..., 0], a[..., 1] - b[..., 1]
    return np.stack([c * dx + s * dy, -s * dx + c * dy, angle_diff(a[..., 2], b[..., 2])], axis=-1)
