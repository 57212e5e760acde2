"""Named anchors on a map: where the robot stands (x, y in metres, yaw in radians) for each
location id, stored next to the map as ``<map>.anchors.yaml``::

    frame: map
    anchors:
      desk_01: {x: 5.0, y: 6.0, yaw: -1.5708}
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import yaml

from assistantx.core.errors import MapError
from assistantx.nav.occupancy_map import read_yaml


@dataclass(frozen=True)
class Anchor:
    x: float
    y: float
    yaw: float = 0.0


def load_anchors(path: str | Path) -> dict[str, Anchor]:
    """Read an anchors file; raise MapError naming the file and the bad entry."""
    file = Path(path)
    doc = read_yaml(file, "anchors")
    if not isinstance(doc, dict) or not isinstance(doc.get("anchors"), dict):
        raise MapError(f"{file}: expected a mapping with an 'anchors' mapping")
    anchors: dict[str, Anchor] = {}
    for name, entry in doc["anchors"].items():
        if not isinstance(entry, dict) or not {"x", "y"} <= entry.keys():
            raise MapError(f"{file}: anchor {name!r} needs x and y")
        try:
            values = [float(entry["x"]), float(entry["y"]), float(entry.get("yaw", 0.0))]
        except (TypeError, ValueError) as exc:
            raise MapError(f"{file}: anchor {name!r} has a non-numeric coordinate") from exc
        if not all(math.isfinite(v) for v in values):
            raise MapError(f"{file}: anchor {name!r} has a non-finite coordinate")
        anchors[str(name)] = Anchor(*values)
    return anchors


def save_anchors(anchors: Mapping[str, Anchor], path: str | Path) -> None:
    doc = {
        "frame": "map",
        "anchors": {
            name: {"x": a.x, "y": a.y, "yaw": round(a.yaw, 4)} for name, a in anchors.items()
        },
    }
    Path(path).write_text(yaml.safe_dump(doc, sort_keys=False), encoding="utf-8")
