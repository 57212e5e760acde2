"""``assistantx map render``: draw a map (with its anchors when it has them), a planned path
and AMCL's particle cloud to a PNG (``--out``, default ``maps/`` inside the data directory, never
the current working tree). ``assistantx map check``: does every office location have an anchor
in free space the robot fits in, reachable from the others?"""

from __future__ import annotations

import argparse
import asyncio
from pathlib import Path

import numpy as np

from assistantx.adapters.robot.navigator import DEFAULT_MAP, NavigatorRobot
from assistantx.core.clock import SimClock
from assistantx.core.errors import AssistantXError
from assistantx.core.office import DEFAULT_OFFICE, load_office
from assistantx.core.settings import Settings
from assistantx.memory.resolve import Resolver
from assistantx.nav.anchor_check import check_anchors
from assistantx.nav.anchors import Anchor, load_anchors
from assistantx.nav.costmap import Costmap
from assistantx.nav.navigation import NavigationParams
from assistantx.nav.occupancy_map import load_map
from assistantx.nav.render import render_map


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = sub.add_parser("map", help="robot map tools")
    map_sub = parser.add_subparsers(dest="map_command", required=True, metavar="ACTION")
    render = map_sub.add_parser("render", help="render the map, anchors, a path, particles")
    render.add_argument(
        "--out", type=Path, default=None, help="PNG file to write (default: DATA/maps/NAME.png)"
    )
    render.add_argument("--map", type=Path, default=DEFAULT_MAP, help="map_server YAML")
    render.add_argument("--anchors", type=Path, default=None, help="anchors YAML")
    render.add_argument("--office", type=Path, default=DEFAULT_OFFICE, help="office YAML")
    render.add_argument(
        "--path",
        default=None,
        metavar="A,B",
        help="plan (and drive) from A to B: people (their desks), facilities or locations",
    )
    render.add_argument("--particles", action="store_true", help="show AMCL's particle cloud")
    render.add_argument("--seed", type=int, default=0)
    render.set_defaults(func=run_render)
    check = map_sub.add_parser("check", help="check an office's anchors against a map")
    check.add_argument("--map", type=Path, default=DEFAULT_MAP, help="map_server YAML")
    check.add_argument("--anchors", type=Path, default=None, help="anchors YAML")
    check.add_argument("--office", type=Path, default=DEFAULT_OFFICE, help="office YAML")
    check.set_defaults(func=run_check)


def _anchors_path(map_yaml: Path, anchors: Path | None) -> Path:
    return anchors or map_yaml.with_name(map_yaml.stem + ".anchors.yaml")


def run_check(args: argparse.Namespace) -> int:
    """One line per problem: file, location id, problem; exit 1 if there is any."""
    try:
        office = load_office(args.office)
        grid = load_map(args.map)
        path = _anchors_path(args.map, args.anchors)
        anchors = load_anchors(path)
    except AssistantXError as exc:
        print(f"error: {exc}")
        return 1
    lines = [
        f"{path}: location {loc.id!r} has no anchor"
        for loc in office.locations
        if loc.id not in anchors
    ]
    used = {k: v for k, v in anchors.items() if k in {loc.id for loc in office.locations}}
    lines += [
        f"{path}: location {p.anchor!r}: {p.problem}"
        for p in check_anchors(Costmap.inflate(grid), used)
    ]
    for line in lines:
        print(line)
    if not lines:
        print(f"{path}: {len(used)} anchors, all in free space and reachable from each other")
    return 1 if lines else 0


def run_render(args: argparse.Namespace) -> int:
    try:
        return asyncio.run(_render(args))
    except AssistantXError as exc:
        print(f"error: {exc}")
        return 1


def _render_plain(args: argparse.Namespace) -> int:
    """The map alone, with its anchors if there is an anchors file: no office needed."""
    grid = load_map(args.map)
    path = _anchors_path(args.map, args.anchors)
    anchors: dict[str, Anchor] | None = None
    if args.anchors is not None or path.is_file():
        anchors = load_anchors(path)
    out = render_map(grid, args.out, anchors=anchors)
    print(f"wrote {out}" + ("" if anchors else " (no anchors)"))
    return 0


async def _render(args: argparse.Namespace) -> int:
    if not args.path and not args.particles:
        return _render_plain(args)
    office = load_office(args.office)
    start, goal = None, None
    if args.path:
        parts = [p.strip() for p in args.path.split(",")]
        if len(parts) != 2 or not all(parts):
            print("error: --path takes two places, e.g. --path Lee,'print room' or desk_01,desk_02")
            return 2
        # Places are named as everywhere else (a person's desk, a facility, a location, in any
        # case): the one resolver turns them into the location ids the anchors are keyed by.
        resolver = Resolver(office)
        start, goal = resolver.place(parts[0]), resolver.place(parts[1])
    robot = NavigatorRobot.from_files(
        office,
        SimClock(),
        args.seed,
        map_yaml=args.map,
        anchors_yaml=args.anchors,
        localize=args.particles,
        start=start,
        # One plan and one drive, with no requests to keep serving meanwhile: planned here,
        # not in a worker process spawned for it (about a CPU-second to start).
        params=NavigationParams(plan_in_process=False) if args.particles else None,
    )
    path = None
    if goal is not None:
        path = robot.plan_to(goal).points
        if args.particles:  # drive there, so the cloud shows localization after the trip
            await robot.move_to(goal)
    state = robot.state()
    particles = np.array(state.particles) if state.particles else None
    target: Path = args.out or default_out(Settings().data_dir, args.map, start, goal)
    target.parent.mkdir(parents=True, exist_ok=True)
    out = render_map(robot.grid, target, anchors=robot.anchors, path=path, particles=particles)
    length = f", path {robot.path_distance(start, goal):.2f} m" if start and goal else ""
    print(f"wrote {out}{length}")
    return 0


def default_out(data_dir: Path, map_yaml: Path, start: str | None, goal: str | None) -> Path:
    """``DATA/maps/office.png``, or ``DATA/maps/office-desk_03-print_room.png`` with a path."""
    name = "-".join(p for p in (map_yaml.stem, start, goal) if p)
    return data_dir / "maps" / f"{name}.png"
