"""Generate the default office floor plan (maps/office.*) from a list of rectangles.

The floor is 40 x 25 m at 5 cm per cell, origin (0, 0) at the lower-left corner, so map
coordinates equal the x, y of dataset/office.yaml. It holds an open-plan area with two rows
of eight desks (the anchors stand 1 m in front of each desk), a middle aisle with cabinets
and pillars placed unevenly (so that no two spots look alike to the LiDAR), a print room
and a meeting room with doors, a kitchen strip (coffee, water, fridge, kitchenette) behind a
wall with three doors, and a vending area.

Run ``python -m assistantx.nav.office_map_gen maps/`` to rewrite the committed files.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Iterable
from pathlib import Path

import numpy as np
import yaml

from assistantx.nav.anchors import Anchor, save_anchors
from assistantx.nav.occupancy_map import FREE, OCCUPIED, OccupancyMap, save_map

WIDTH_M = 40.0
HEIGHT_M = 25.0
RESOLUTION = 0.05

Rect = tuple[float, float, float, float]  # x0, y0, x1, y1 in metres

DESK_XS = (5.0, 9.0, 13.0, 17.0, 21.0, 25.0, 29.0, 33.0)
WALL = 0.2
INNER = 0.15


def _outer_walls() -> list[Rect]:
    return [
        (0.0, 0.0, WIDTH_M, WALL),
        (0.0, HEIGHT_M - WALL, WIDTH_M, HEIGHT_M),
        (0.0, 0.0, WALL, HEIGHT_M),
        (WIDTH_M - WALL, 0.0, WIDTH_M, HEIGHT_M),
    ]


def _wall_with_doors(
    fixed: float, start: float, end: float, doors: Iterable[tuple[float, float]], *, along_x: bool
) -> list[Rect]:
    """A wall at ``fixed`` running from start to end, with gaps at ``doors`` (from, to)."""
    edges = [start]
    for door_from, door_to in sorted(doors):
        edges += [door_from, door_to]
    edges.append(end)
    half = INNER / 2
    rects: list[Rect] = []
    for a, b in zip(edges[::2], edges[1::2], strict=True):
        if b > a:
            rects.append(
                (a, fixed - half, b, fixed + half)
                if along_x
                else (fixed - half, a, fixed + half, b)
            )
    return rects


def office_rectangles() -> list[Rect]:
    rects = _outer_walls()
    # Desk rows: row A tables below the y = 6 anchors, row B tables above the y = 13 anchors.
    rects += [(x - 1.1, 3.8, x + 1.1, 5.0) for x in DESK_XS]
    rects += [(x - 1.1, 14.0, x + 1.1, 15.2) for x in DESK_XS]
    # Filing cabinets along the south wall, in uneven runs.
    rects += [(2.0, WALL, 10.0, 0.8), (14.0, WALL, 17.5, 0.8), (24.0, WALL, 31.5, 0.8)]
    # Middle aisle: two low cabinet runs, two pillars and a plant, deliberately irregular.
    rects += [(6.5, 9.3, 11.5, 9.8), (20.5, 9.3, 27.5, 9.8)]
    rects += [(15.0, 9.3, 15.5, 9.8), (31.2, 8.8, 31.7, 9.3), (1.5, 9.0, 2.1, 9.6)]
    # Wall between the open plan and the facilities strip, with four doors.
    rects += _wall_with_doors(
        18.0, WALL, 35.4, [(2.8, 4.6), (9.5, 12.0), (18.5, 21.0), (27.5, 30.0)], along_x=True
    )
    # Meeting room (east): wall at x = 35.5 with a door, table and a cabinet inside.
    rects += _wall_with_doors(35.5, WALL, 18.0, [(9.0, 10.6)], along_x=False)
    rects += [(35.4, 17.93, WIDTH_M, 18.07)]
    rects += [(36.5, 2.5, 38.6, 5.5), (38.9, 12.0, 39.8, 15.0)]
    # Print room (north-west): east wall, printer on the west wall, shelves.
    rects += [(7.93, 18.0, 8.07, HEIGHT_M)]
    rects += [(WALL, 19.8, 1.9, 21.4), (4.8, 23.6, 7.93, 24.8)]
    # Kitchen strip: counter along the north wall with a gap by the fridge, a fridge box.
    rects += [(9.0, 22.3, 20.0, 24.8), (24.2, 22.3, 33.0, 24.8), (22.0, 23.4, 24.0, 24.8)]
    # Wall to the vending area with a door, vending machines and a sofa.
    rects += _wall_with_doors(34.0, 18.0, HEIGHT_M, [(19.4, 21.6)], along_x=False)
    rects += [(35.8, 23.2, 38.4, 24.8), (39.0, 18.6, 39.8, 20.4)]
    return rects


def office_anchors(locations: Iterable[tuple[str, float, float]]) -> dict[str, Anchor]:
    """Anchors at the office coordinates, facing what the robot serves there."""
    anchors: dict[str, Anchor] = {}
    for location_id, x, y in locations:
        if location_id.startswith("desk_"):
            yaw = -math.pi / 2 if y < 9.5 else math.pi / 2
        elif location_id == "print_room":
            yaw = math.pi
        elif location_id == "meeting_room":
            yaw = -math.pi / 2
        else:
            yaw = math.pi / 2
        anchors[location_id] = Anchor(x, y, yaw)
    return anchors


def rasterize(rects: Iterable[Rect]) -> OccupancyMap:
    height = round(HEIGHT_M / RESOLUTION)
    width = round(WIDTH_M / RESOLUTION)
    data = np.full((height, width), FREE, dtype=np.int8)
    for x0, y0, x1, y1 in rects:
        ix0, ix1 = round(x0 / RESOLUTION), round(x1 / RESOLUTION)
        iy0, iy1 = round(y0 / RESOLUTION), round(y1 / RESOLUTION)
        data[max(iy0, 0) : max(iy1, iy0 + 1), max(ix0, 0) : max(ix1, ix0 + 1)] = OCCUPIED
    return OccupancyMap(data, RESOLUTION)


def generate(out_dir: Path, office_yaml: Path) -> None:
    # Only ids and coordinates are needed; reading them directly keeps robot/ free of the
    # assistant's office model (robot algorithms know nothing of the assistant).
    office = yaml.safe_load(office_yaml.read_text(encoding="utf-8"))
    grid = rasterize(office_rectangles())
    out_dir.mkdir(parents=True, exist_ok=True)
    save_map(grid, out_dir / "office.yaml")
    save_anchors(
        office_anchors(
            (loc["id"], float(loc["x"]), float(loc["y"])) for loc in office["locations"]
        ),
        out_dir / "office.anchors.yaml",
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir", type=Path)
    parser.add_argument("--office", type=Path, default=Path("dataset/office.yaml"))
    args = parser.parse_args()
    generate(args.out_dir, args.office)


if __name__ == "__main__":
    main()
