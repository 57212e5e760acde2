"""Render a map with its anchors, a path and a particle cloud to a PNG (matplotlib, Agg)."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import numpy as np

from assistantx.nav.anchors import Anchor
from assistantx.nav.geometry import FloatArray
from assistantx.nav.occupancy_map import OccupancyMap


def render_map(
    grid: OccupancyMap,
    out: str | Path,
    *,
    anchors: Mapping[str, Anchor] | None = None,
    path: FloatArray | None = None,
    particles: FloatArray | None = None,
    dpi: int = 120,
) -> Path:
    from matplotlib.figure import Figure  # no pyplot: no global state, no GUI backend

    width_m, height_m = grid.size_m
    fig = Figure(figsize=(max(4.0, width_m / 4), max(3.0, height_m / 4)), dpi=dpi)
    ax = fig.add_subplot()
    shade = np.where(grid.data < 0, 0.8, 1.0 - np.clip(grid.data, 0, 100) / 100.0)
    extent = (grid.origin_x, grid.origin_x + width_m, grid.origin_y, grid.origin_y + height_m)
    image = ax.imshow(shade, cmap="gray", vmin=0, vmax=1, origin="lower", extent=extent)
    if grid.origin_yaw:  # map_server's origin yaw turns the grid about its lower-left corner
        from matplotlib.transforms import Affine2D

        turn = Affine2D().rotate_around(grid.origin_x, grid.origin_y, grid.origin_yaw)
        image.set_transform(turn + ax.transData)
        corners = np.array(
            turn.transform(
                [extent[::2], extent[1::2], (extent[0], extent[3]), (extent[1], extent[2])]
            )
        )
        ax.set_xlim(corners[:, 0].min(), corners[:, 0].max())
        ax.set_ylim(corners[:, 1].min(), corners[:, 1].max())
    if particles is not None and len(particles):
        ax.quiver(
            particles[:, 0],
            particles[:, 1],
            np.cos(particles[:, 2]),
            np.sin(particles[:, 2]),
            color="tab:red",
            alpha=0.4,
            scale=60,
            width=0.002,
        )
    if path is not None and len(path):
        ax.plot(path[:, 0], path[:, 1], color="tab:blue", linewidth=1.5)
    for name, anchor in (anchors or {}).items():
        ax.plot(anchor.x, anchor.y, "o", color="tab:green", markersize=3)
        ax.annotate(
            name, (anchor.x, anchor.y), fontsize=5, xytext=(2, 2), textcoords="offset points"
        )
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_aspect("equal")
    target = Path(out)
    fig.savefig(target, bbox_inches="tight")
    return target
