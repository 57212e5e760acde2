"""Scenario files: what differs between a map and the world on one day, as seeded data.

A scenario is a YAML file (maps/scenarios/*.yaml)::

    map: ../nav2/depot.yaml        # a map_server YAML, relative to this file
    seed: 3                        # people's starting points and the sensor noise
    start: [2.0, 2.0, 0.0]         # the robot's pose, x m, y m, yaw rad
    legs:                          # where it is sent, in order
      - {name: the loading bay, x: 27.0, y: 12.0, yaw: 0.0}
    boxes:                         # furniture moved, pallets dropped, a corridor blocked
      - {name: a pallet, x: 10.0, y: 7.5, width: 1.2, depth: 0.8}
    doors:                         # closed doors, as segments
      - {name: the meeting room door, from: [35.5, 9.0], to: [35.5, 10.6]}
      - {name: the kitchen door, from: [..], to: [..], opens_after: 600}  # opened then (s)
    people:                        # walking to and fro along a path
      - {path: [[3, 10], [30, 10]], speed: 1.2, radius: 0.25}
    expect:                        # per leg, optional: "arrive" or "blocked"
      - arrive

Anything malformed is a ScenarioError naming the file and the field.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from assistantx.core.clock import Clock
from assistantx.core.errors import MapError
from assistantx.nav.ground_truth import Box, Door, GroundTruth, WalkerSpec
from assistantx.nav.occupancy_map import OccupancyMap, load_map


class ScenarioError(MapError):
    """A scenario file that cannot be read or has a malformed field."""


@dataclass(frozen=True)
class Leg:
    name: str
    x: float
    y: float
    yaw: float
    expect: str = "arrive"  # or "blocked": no way there in this world, to be reported


@dataclass(frozen=True)
class Scenario:
    name: str
    map_yaml: Path
    seed: int
    start: tuple[float, float, float]
    legs: tuple[Leg, ...]
    boxes: tuple[Box, ...] = ()
    doors: tuple[Door, ...] = ()
    people: tuple[WalkerSpec, ...] = ()

    def load_map(self) -> OccupancyMap:
        return load_map(self.map_yaml)

    def world(self, grid: OccupancyMap, robot_radius_m: float = 0.25) -> GroundTruth:
        return GroundTruth(
            grid,
            boxes=self.boxes,
            doors=self.doors,
            walkers=self.people,
            rng=np.random.default_rng(self.seed),
            robot_radius_m=robot_radius_m,
        )


def schedule_events(scenario: Scenario, world: GroundTruth, clock: Clock) -> None:
    """Put the scenario's events on ``clock``: each door with ``opens_after`` opens then."""
    for door in scenario.doors:
        if door.opens_after_s is not None:
            clock.call_later(door.opens_after_s, functools.partial(world.open_door, door.name))


def load_scenario(path: str | Path) -> Scenario:
    path = Path(path)
    try:
        raw = yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        raise ScenarioError(f"{path}: cannot read scenario: {exc}") from exc
    if not isinstance(raw, dict):
        raise ScenarioError(f"{path}: a scenario is a YAML mapping")
    try:
        return _parse(path, raw)
    except (KeyError, TypeError, ValueError, IndexError) as exc:
        raise ScenarioError(f"{path}: malformed scenario: {exc!r}") from exc


def _parse(path: Path, raw: dict[str, Any]) -> Scenario:
    map_yaml = (path.parent / str(raw["map"])).resolve()
    if not map_yaml.is_file():
        raise ScenarioError(f"{path}: map {raw['map']!r} not found")
    expect = list(raw.get("expect", []))
    legs = []
    for i, leg in enumerate(raw["legs"]):
        outcome = str(leg.get("expect", expect[i] if i < len(expect) else "arrive"))
        if outcome not in ("arrive", "blocked"):
            raise ScenarioError(f"{path}: leg {i}: expect must be 'arrive' or 'blocked'")
        legs.append(
            Leg(
                str(leg["name"]),
                float(leg["x"]),
                float(leg["y"]),
                float(leg.get("yaw", 0.0)),
                outcome,
            )
        )
    start = tuple(float(v) for v in raw["start"])
    if len(start) != 3 or not all(math.isfinite(v) for v in start):
        raise ScenarioError(f"{path}: start must be [x, y, yaw]")
    return Scenario(
        name=path.stem,
        map_yaml=map_yaml,
        seed=int(raw.get("seed", 0)),
        start=(start[0], start[1], start[2]),
        legs=tuple(legs),
        boxes=tuple(
            Box(
                float(b["x"]),
                float(b["y"]),
                float(b["width"]),
                float(b["depth"]),
                str(b.get("name", "an obstacle")),
            )
            for b in raw.get("boxes", [])
        ),
        doors=tuple(
            Door(
                _point(d["from"]),
                _point(d["to"]),
                str(d.get("name", "a door")),
                opens_after_s=float(d["opens_after"]) if "opens_after" in d else None,
            )
            for d in raw.get("doors", [])
        ),
        people=tuple(
            WalkerSpec(
                tuple(_point(p) for p in w["path"]),
                float(w.get("speed", 1.2)),
                float(w.get("radius", 0.25)),
            )
            for w in raw.get("people", [])
        ),
    )


def _point(value: Any) -> tuple[float, float]:
    x, y = value
    return float(x), float(y)
