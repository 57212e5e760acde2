"""Anchors against a map: is each in free space the robot can stand in, and can the robot
drive between all of them? Also places anchors on a map that has none (benchmarks, trying a
new map before anyone has named its places).

Reachability is one connected-component labelling of the cells the robot's centre may
occupy (4-connected, as strict as the planner, which cuts no corners), so checking every
pair of n anchors costs one pass over the grid, not n² plans.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from assistantx.nav.anchors import Anchor
from assistantx.nav.costmap import INSCRIBED, LETHAL, NO_INFORMATION, Costmap


@dataclass(frozen=True)
class AnchorProblem:
    anchor: str
    problem: str


def _components(costmap: Costmap) -> npt.NDArray[np.int32]:
    from scipy.ndimage import label  # here: importing the checks costs no scipy

    labels, _ = label(costmap.traversable)
    return np.asarray(labels, dtype=np.int32)


def check_anchors(
    costmap: Costmap,
    anchors: Mapping[str, Anchor],
    components: npt.NDArray[np.int32] | None = None,
) -> list[AnchorProblem]:
    """Every anchor that is off the map, in a wall, in unknown space, too close to a wall
    for the robot, or cut off from the others (the largest group of mutually reachable
    anchors counts as "the others"). ``components``: the traversable cells' labels when the
    caller has them (a planner on this costmap), else computed."""
    grid = costmap.grid
    labels = _components(costmap) if components is None else components
    problems: list[AnchorProblem] = []
    component: dict[str, int] = {}
    for name, a in anchors.items():
        ix, iy = (int(v) for v in grid.world_to_cell(a.x, a.y))
        where = f"({a.x:.2f}, {a.y:.2f})"
        if not (0 <= ix < grid.width and 0 <= iy < grid.height):
            problems.append(AnchorProblem(name, f"{where} is off the map"))
            continue
        cost = int(costmap.costs[iy, ix])
        if cost == LETHAL:
            problems.append(AnchorProblem(name, f"{where} is inside an obstacle"))
        elif cost == NO_INFORMATION:
            problems.append(AnchorProblem(name, f"{where} is in unknown space"))
        elif cost >= INSCRIBED:
            problems.append(
                AnchorProblem(name, f"{where} is closer to a wall than the robot's radius")
            )
        else:
            component[name] = int(labels[iy, ix])
    if component:
        sizes = np.bincount(np.fromiter(component.values(), dtype=np.int64))
        main = int(np.argmax(sizes))
        for name, comp in component.items():
            if comp != main:
                a = anchors[name]
                problems.append(
                    AnchorProblem(
                        name,
                        f"({a.x:.2f}, {a.y:.2f}) cannot be reached from the other anchors",
                    )
                )
    return problems


def place_anchors(
    costmap: Costmap, count: int, rng: np.random.Generator, *, clearance_m: float = 0.5
) -> dict[str, Anchor]:
    """``count`` anchors spread over the largest reachable free area: cells at least
    ``clearance_m`` from any wall, chosen by farthest-point sampling from a seeded start."""
    labels = _components(costmap)
    if not labels.any():
        raise ValueError("the map has no free space the robot can stand in")
    sizes = np.bincount(labels.ravel())
    sizes[0] = 0
    main = labels == int(np.argmax(sizes))
    roomy = main & (costmap.obstacle_distance_m >= clearance_m) & (costmap.costs == 0)
    iy, ix = np.nonzero(roomy if roomy.any() else main)
    xs, ys = costmap.grid.cell_to_world(ix, iy)
    points = np.column_stack([xs, ys])
    chosen = [int(rng.integers(len(points)))]
    nearest = np.hypot(*(points - points[chosen[0]]).T)
    while len(chosen) < min(count, len(points)):
        nxt = int(np.argmax(nearest))
        chosen.append(nxt)
        nearest = np.minimum(nearest, np.hypot(*(points - points[nxt]).T))
    return {
        f"anchor_{k:02d}": Anchor(
            float(points[i, 0]), float(points[i, 1]), float(rng.uniform(-math.pi, math.pi))
        )
        for k, i in enumerate(chosen)
    }
