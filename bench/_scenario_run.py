"""One scenario run for bench/robot_real_maps.py --scenario: the robot (AMCL, LiDAR, obstacle
layer, collision monitor, recoveries) drives the scenario's legs in its simulated world, and
the run is measured against the world's truth, with a picture of it."""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from assistantx.core.errors import DoorClosedError, RobotError, UnreachableError
from assistantx.nav.ground_truth import GroundTruth
from assistantx.nav.navigation import Navigator
from assistantx.nav.scenario import Scenario

DETOUR_FACTOR = 1.1  # a leg is a detour when driven > 1.1 x the map's way + 0.5 m
DETOUR_SLACK_M = 0.5


def run_scenario(scenario: Scenario, png: Path | None) -> dict[str, object]:
    started = time.process_time()
    grid = scenario.load_map()
    world = GroundTruth(
        grid,
        boxes=scenario.boxes,
        doors=scenario.doors,
        walkers=scenario.people,
        rng=np.random.default_rng(scenario.seed),
        trail_every_s=0.5,
    )
    nav = Navigator(
        grid, np.array(scenario.start), np.random.default_rng(scenario.seed), world=world
    )
    legs: list[dict[str, object]] = []
    track: list[tuple[float, float]] = []
    for leg in scenario.legs:
        here = (float(nav.base.true_pose[0]), float(nav.base.true_pose[1]))
        try:
            map_way = nav.map_planner.plan(here, (leg.x, leg.y)).length_m
        except UnreachableError:
            map_way = math.nan
        odometer = nav.base.odometer_m
        recoveries = len(nav.recoveries)
        outcome, said = "arrived", ""
        try:
            for _seconds in nav.navigate((leg.x, leg.y), leg.yaw):
                track.append((float(nav.base.true_pose[0]), float(nav.base.true_pose[1])))
        except DoorClosedError as exc:
            outcome, said = "door closed", str(exc)
        except RobotError as exc:
            outcome, said = type(exc).__name__, str(exc)
        driven = nav.base.odometer_m - odometer
        true = nav.base.true_pose
        legs.append(
            {
                "leg": leg.name,
                "expected": leg.expect,
                "outcome": outcome,
                "as_expected": (outcome == "arrived") == (leg.expect == "arrive"),
                "driven_m": round(driven, 1),
                "map_way_m": round(map_way, 1),
                "detour": outcome == "arrived"
                and driven > DETOUR_FACTOR * map_way + DETOUR_SLACK_M,
                "recoveries": nav.recoveries[recoveries:],
                "arrival_error_m": round(math.hypot(true[0] - leg.x, true[1] - leg.y), 3),
                "said": said,
            }
        )
    errors = np.array([math.dist(s.true_pose[:2], s.estimate[:2]) for s in nav.tracking])
    result: dict[str, object] = {
        "scenario": scenario.name,
        "map": scenario.map_yaml.stem,
        "legs": len(legs),
        "legs_driven": sum(leg["outcome"] == "arrived" for leg in legs),
        "legs_reported": sum(leg["outcome"] != "arrived" for leg in legs),
        "legs_as_expected": sum(bool(leg["as_expected"]) for leg in legs),
        "distance_m": round(nav.base.odometer_m, 1),
        "collisions": nav.safety.collisions,
        "near_misses": nav.safety.near_misses,
        "min_clearance_m": round(nav.safety.min_clearance_m, 3),
        "monitor_stops_s": round(nav.safety.stops * nav.params.drive.dt_s, 1),
        "detours": sum(bool(leg["detour"]) for leg in legs),
        "unmapped_return_share": round(float(np.mean(nav.unmapped_shares)), 3),
        "mean_position_error_m": round(float(errors.mean()), 4),
        "p95_position_error_m": round(float(np.percentile(errors, 95)), 4),
        "max_position_error_m": round(float(errors.max()), 4),
        "cpu_s": round(time.process_time() - started, 1),
        "per_leg": legs,
    }
    if png is not None:
        draw_run(world, nav, np.array(track), scenario, png)
        result["png"] = str(png)
    return result


def draw_run(
    world: GroundTruth, nav: Navigator, track: np.ndarray, scenario: Scenario, out: Path
) -> None:
    """The map (grey), what the world adds (red), the robot's true track (blue), the
    people's walks (green), the legs' goals (black crosses), collisions (red circles)."""
    from matplotlib.figure import Figure  # no pyplot: no global state, no GUI backend
    from matplotlib.patches import Circle

    grid = world.grid
    width_m, height_m = grid.size_m
    fig = Figure(figsize=(max(5.0, width_m / 3), max(4.0, height_m / 3)), dpi=100)
    ax = fig.add_subplot()
    shade = np.where(grid.data < 0, 0.8, 1.0 - np.clip(grid.data, 0, 100) / 100.0)
    rgb = np.repeat(shade[:, :, None], 3, axis=2)
    added = world.static & ~grid.obstacles & (grid.data >= 0)
    rgb[added] = (0.85, 0.2, 0.2)
    extent = (grid.origin_x, grid.origin_x + width_m, grid.origin_y, grid.origin_y + height_m)
    ax.imshow(rgb, origin="lower", extent=extent, interpolation="nearest")
    for trail in world.trails:
        if trail:
            xy = np.array(trail)
            ax.plot(xy[:, 0], xy[:, 1], color="tab:green", lw=0.6, alpha=0.6)
    if len(track):
        ax.plot(track[:, 0], track[:, 1], color="tab:blue", lw=1.2, label="robot (true)")
    for leg in scenario.legs:
        ax.plot(leg.x, leg.y, "kx")
        ax.annotate(leg.name, (leg.x, leg.y), fontsize=6)
    for x, y in nav.safety.collision_points:
        ax.add_patch(Circle((x, y), 0.4, fill=False, color="red"))
    people = world.people
    if len(people):
        ax.plot(people[:, 0], people[:, 1], "o", color="tab:green", ms=4, label="people")
    ax.set_title(
        f"{scenario.name}: {nav.safety.collisions} collisions, {nav.safety.near_misses} near misses"
    )
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.legend(loc="upper right", fontsize=6)
    fig.savefig(out)
