"""Time one full AMCL update (motion + sensor + resample + estimate) on the office map,
for 2000 and 20000 particles x 60 beams, against a straightforward per-particle loop
(kept here as the reference, not in src/). min_particles = max_particles, so KLD does not
shrink the set between timed updates.

Run: python bench/robot_amcl_speed.py
"""

from __future__ import annotations

import json
import math
import statistics
import time
from pathlib import Path

import numpy as np

from assistantx.nav.amcl import AmclParams, LikelihoodField, ParticleFilter
from assistantx.nav.lidar import LaserScan, Lidar
from assistantx.nav.occupancy_map import OccupancyMap, load_map

REPO = Path(__file__).resolve().parents[1]


class LoopAmcl:
    """The same update written particle by particle, beam by beam, as a first port would."""

    def __init__(self, grid: OccupancyMap, params: AmclParams, rng: np.random.Generator) -> None:
        self.grid, self.params, self.rng = grid, params, rng
        self.field = LikelihoodField(grid, params)

    def update(
        self,
        particles: list[list[float]],
        odom_prev: np.ndarray,
        odom_now: np.ndarray,
        scan: LaserScan,
    ) -> tuple[list[list[float]], tuple[float, float, float]]:
        p, rng, grid = self.params, self.rng, self.grid
        dx, dy = odom_now[0] - odom_prev[0], odom_now[1] - odom_prev[1]
        trans = math.hypot(dx, dy)
        rot1 = math.atan2(dy, dx) - odom_prev[2] if trans > 0.01 else 0.0
        rot2 = odom_now[2] - odom_prev[2] - rot1
        weights = []
        step = max(1, (len(scan.ranges) - 1) // (p.max_beams - 1))
        beams = [
            (float(scan.ranges[i]), float(scan.angles[i])) for i in range(0, len(scan.ranges), step)
        ]
        for particle in particles:
            r1 = rot1 - rng.normal(0, math.sqrt(p.alpha1 * rot1**2 + p.alpha2 * trans**2))
            t = trans - rng.normal(
                0, math.sqrt(p.alpha3 * trans**2 + p.alpha4 * (rot1**2 + rot2**2))
            )
            r2 = rot2 - rng.normal(0, math.sqrt(p.alpha1 * rot2**2 + p.alpha2 * trans**2))
            particle[0] += t * math.cos(particle[2] + r1)
            particle[1] += t * math.sin(particle[2] + r1)
            particle[2] += r1 + r2
            log_w = 0.0
            for rng_m, angle in beams:
                if rng_m >= scan.range_max:
                    continue
                ex = particle[0] + rng_m * math.cos(particle[2] + angle)
                ey = particle[1] + rng_m * math.sin(particle[2] + angle)
                ix = int((ex - grid.origin_x) / grid.resolution)
                iy = int((ey - grid.origin_y) / grid.resolution)
                if 0 <= ix < grid.width and 0 <= iy < grid.height:
                    log_w += self.field.log_p[iy * grid.width + ix]
                else:
                    log_w += self.field.log_p_off_map
            weights.append(log_w)
        top = max(weights)
        w = [math.exp(v - top) for v in weights]
        total = sum(w)
        # Systematic resampling, one draw at a time.
        n = len(particles)
        out, cumulative, i = [], w[0] / total, 0
        u = rng.random() / n
        for k in range(n):
            target = u + k / n
            while target > cumulative and i < n - 1:
                i += 1
                cumulative += w[i] / total
            out.append(list(particles[i]))
        sx = sum(q[0] * wi for q, wi in zip(particles, w, strict=True)) / total
        sy = sum(q[1] * wi for q, wi in zip(particles, w, strict=True)) / total
        sc = sum(math.cos(q[2]) * wi for q, wi in zip(particles, w, strict=True))
        ss = sum(math.sin(q[2]) * wi for q, wi in zip(particles, w, strict=True))
        return out, (sx, sy, math.atan2(ss, sc))


def time_vectorized(
    grid: OccupancyMap, n: int, scan: LaserScan, pose: np.ndarray, reps: int
) -> float:
    params = AmclParams(min_particles=n, max_particles=n)
    rng = np.random.default_rng(1)
    pf = ParticleFilter(grid, params, rng)
    pf.initialize(pose)
    odom = pose.copy()
    times = []
    for _ in range(reps):
        odom = odom + np.array([0.1, 0.0, 0.02])
        t0 = time.perf_counter()
        pf.update(odom, scan, force=True)
        times.append(time.perf_counter() - t0)
        assert len(pf.particles) == n
    return statistics.median(times) * 1000


def time_loop(grid: OccupancyMap, n: int, scan: LaserScan, pose: np.ndarray, reps: int) -> float:
    rng = np.random.default_rng(1)
    loop = LoopAmcl(grid, AmclParams(), rng)
    particles = [list(pose + rng.normal(0, 0.1, 3)) for _ in range(n)]
    odom = pose.copy()
    times = []
    for _ in range(reps):
        new = odom + np.array([0.1, 0.0, 0.02])
        t0 = time.perf_counter()
        particles, _ = loop.update(particles, odom, new, scan)
        times.append(time.perf_counter() - t0)
        odom = new
    return statistics.median(times) * 1000


def main() -> None:
    grid = load_map(REPO / "maps" / "office.yaml")
    pose = np.array([17.0, 9.0, 0.3])
    scan = Lidar(grid).scan(pose, np.random.default_rng(0))
    result: dict[str, float] = {}
    for n, reps, loop_reps in [(2000, 50, 3), (20000, 10, 1)]:
        fast = time_vectorized(grid, n, scan, pose, reps)
        slow = time_loop(grid, n, scan, pose, loop_reps)
        result[f"update_ms_{n}"] = round(fast, 2)
        result[f"loop_ms_{n}"] = round(slow, 1)
        result[f"speedup_{n}"] = round(slow / fast, 1)
        print(
            f"{n:>6} particles x 60 beams: vectorized {fast:7.2f} ms | per-particle loop "
            f"{slow:8.1f} ms | {slow / fast:5.1f}x"
        )
    print(json.dumps(result))


if __name__ == "__main__":
    main()
