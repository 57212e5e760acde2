"""Occupancy grids in the ROS map_server format: a YAML header next to a PGM/PNG image.

The YAML names ``image`` (relative to the YAML file), ``resolution`` (m/cell), ``origin``
(x, y, yaw of the lower-left pixel, m and rad), ``negate``, ``occupied_thresh``,
``free_thresh`` and ``mode`` (``trinary``, the default, ``scale`` or ``raw``). Images are
stored top row first; in memory row 0 is the *bottom* row, so ``data[iy, ix]`` is the cell
whose lower-left corner is at ``origin + (ix, iy) * resolution``.

Cell values follow nav_msgs/OccupancyGrid: 0 free, 100 occupied, -1 unknown, and in scale
mode 1..99 in between. Readers accept PGM P5 (8 and 16 bit) and P2, and PNG through
matplotlib.image; the writer produces PGM P5 in trinary mode.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import numpy as np
import numpy.typing as npt
import yaml

from assistantx.core.errors import MapError

FREE = 0
OCCUPIED = 100
UNKNOWN = -1

MapMode = Literal["trinary", "scale", "raw"]
_MODES: tuple[MapMode, ...] = ("trinary", "scale", "raw")


@dataclass(frozen=True, eq=False)
class OccupancyMap:
    """A 2D occupancy grid; ``data`` is int8, row 0 at the bottom (``origin_y``)."""

    data: npt.NDArray[np.int8]
    resolution: float
    origin_x: float = 0.0
    origin_y: float = 0.0
    origin_yaw: float = 0.0

    def __post_init__(self) -> None:
        if self.data.ndim != 2 or self.data.size == 0:
            raise MapError(f"map data must be a non-empty 2D grid, got shape {self.data.shape}")
        if not self.resolution > 0:
            raise MapError(f"map resolution must be positive, got {self.resolution}")
        if not math.isfinite(self.origin_yaw):
            raise MapError(f"map origin yaw must be finite, got {self.origin_yaw}")

    @property
    def height(self) -> int:
        return int(self.data.shape[0])

    @property
    def width(self) -> int:
        return int(self.data.shape[1])

    @property
    def size_m(self) -> tuple[float, float]:
        return self.width * self.resolution, self.height * self.resolution

    @property
    def obstacles(self) -> npt.NDArray[np.bool_]:
        """Cells that stop a laser beam: occupied (>= 65 in scale mode); not unknown ones."""
        return self.data >= 65

    @property
    def occupied(self) -> npt.NDArray[np.bool_]:
        """Cells a robot cannot enter: occupied (>= 65 in scale mode) or unknown."""
        return (self.data >= 65) | (self.data < 0)

    def to_grid_frame(
        self, x: npt.ArrayLike, y: npt.ArrayLike
    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Metres from the origin along the grid's rows and columns (map_server's origin is
        the pose of the lower-left pixel, yaw included)."""
        dx = np.asarray(x, dtype=float) - self.origin_x
        dy = np.asarray(y, dtype=float) - self.origin_y
        if self.origin_yaw == 0.0:
            return dx, dy
        c, s = math.cos(self.origin_yaw), math.sin(self.origin_yaw)
        return c * dx + s * dy, -s * dx + c * dy

    def world_to_cell(
        self, x: npt.ArrayLike, y: npt.ArrayLike
    ) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]:
        """Cell indices (ix, iy) of world points, unclipped (may fall off the grid)."""
        gx, gy = self.to_grid_frame(x, y)
        ix = np.floor(gx / self.resolution)
        iy = np.floor(gy / self.resolution)
        return ix.astype(np.int64), iy.astype(np.int64)

    def cell_to_world(
        self, ix: npt.ArrayLike, iy: npt.ArrayLike
    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """World coordinates of cell centres."""
        gx = (np.asarray(ix, dtype=float) + 0.5) * self.resolution
        gy = (np.asarray(iy, dtype=float) + 0.5) * self.resolution
        if self.origin_yaw == 0.0:
            return self.origin_x + gx, self.origin_y + gy
        c, s = math.cos(self.origin_yaw), math.sin(self.origin_yaw)
        return self.origin_x + c * gx - s * gy, self.origin_y + s * gx + c * gy

    def contains(self, x: float, y: float) -> bool:
        ix, iy = self.world_to_cell(x, y)
        return bool(0 <= ix < self.width and 0 <= iy < self.height)

    def is_free(self, x: float, y: float) -> bool:
        if not self.contains(x, y):
            return False
        ix, iy = self.world_to_cell(x, y)
        return bool(self.data[iy, ix] == FREE)

    def with_data(self, data: npt.NDArray[np.int8]) -> OccupancyMap:
        return OccupancyMap(data, self.resolution, self.origin_x, self.origin_y, self.origin_yaw)

    @functools.cached_property
    def unknown_rim(self) -> npt.NDArray[np.bool_]:
        """Unknown cells with a free cell among their 8 neighbours: on a SLAM map, the grey
        edge of the known floor is where the mapping laser stopped, a wall seen edge-on.
        Found once per map (read-only): the checks, the LiDAR and AMCL each asked for it."""
        free = self.data == FREE
        near_free = free.copy()
        near_free[1:, :] |= free[:-1, :]
        near_free[:-1, :] |= free[1:, :]
        near_free[:, 1:] |= near_free[:, :-1].copy()
        near_free[:, :-1] |= near_free[:, 1:].copy()
        rim = np.asarray((self.data == UNKNOWN) & near_free, dtype=np.bool_)
        rim.flags.writeable = False
        return rim


# -- reading -------------------------------------------------------------------------------
def read_yaml(path: Path, what: str) -> Any:
    """A map's YAML file (its header, its anchors) as read; MapError names the file and
    ``what`` could not be read."""
    try:
        # libyaml's loader when present: the pure-Python one was most of a robot's set-up.
        loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
        return yaml.load(path.read_text(encoding="utf-8"), Loader=loader)
    except (OSError, yaml.YAMLError, UnicodeDecodeError) as exc:
        raise MapError(f"{path}: cannot read {what}: {exc}") from exc


def load_map(yaml_path: str | Path) -> OccupancyMap:
    """Load a map_server map (YAML + image); raise MapError naming the file and the problem."""
    path = Path(yaml_path)
    header = read_yaml(path, "map header")
    if not isinstance(header, dict):
        raise MapError(f"{path}: map header must be a mapping")
    image = _require(header, "image", path)
    resolution = _number(_require(header, "resolution", path), "resolution", path)
    origin = _require(header, "origin", path)
    if not (isinstance(origin, list) and len(origin) == 3):
        raise MapError(f"{path}: origin must be a list [x, y, yaw]")
    ox, oy, oyaw = (_number(v, "origin", path) for v in origin)
    negate = _negate(header.get("negate", 0), path)
    occupied_thresh = _number(header.get("occupied_thresh", 0.65), "occupied_thresh", path)
    free_thresh = _number(header.get("free_thresh", 0.196), "free_thresh", path)
    mode = header.get("mode", "trinary")
    if mode not in _MODES:
        raise MapError(f"{path}: mode must be one of {', '.join(_MODES)}, got {mode!r}")
    if not 0.0 <= free_thresh < occupied_thresh <= 1.0:
        raise MapError(f"{path}: need 0 <= free_thresh < occupied_thresh <= 1")
    image_path = (path.parent / str(image)).resolve()
    convert = functools.partial(
        pixels_to_occupancy,
        negate=negate,
        occupied_thresh=occupied_thresh,
        free_thresh=free_thresh,
        mode=mode,
    )
    levels = _binary_pgm_levels(image_path)
    if levels is not None:
        # Each grey level converted once, then looked up per pixel: the same values as
        # converting every pixel (the conversion is per pixel), without the float arrays
        # of the whole image (~0.03 CPU-s of every start on nav2's warehouse).
        grey, maxval = levels
        every_level = np.arange(np.iinfo(grey.dtype).max + 1, dtype=np.float64)
        table = convert((every_level * (255.0 / maxval)).astype(np.float64, copy=False), None)
        data = table[np.flipud(grey)]
    else:
        pixels, alpha = read_image(image_path)
        data = np.flipud(convert(pixels, alpha)).copy()
    try:
        return OccupancyMap(data, resolution, ox, oy, oyaw)
    except MapError as exc:
        raise MapError(f"{path}: {exc}") from exc


def pixels_to_occupancy(
    pixels: npt.NDArray[np.float64],
    alpha: npt.NDArray[np.float64] | None,
    *,
    negate: bool,
    occupied_thresh: float,
    free_thresh: float,
    mode: MapMode,
) -> npt.NDArray[np.int8]:
    """nav2 map_server's conversion of grey levels (0..255, image order) to occupancy values:
    raw keeps a grey level 0..100 as the value and reads anything else as unknown (so the
    saver's 205 and 254 are unknown, not occupied); scale maps the band between the
    thresholds to ``rint(100 * (occ - free) / (occupied - free))``."""
    if mode == "raw":
        grey = np.rint(pixels)
        return np.where((grey >= 0) & (grey <= 100), grey, UNKNOWN).astype(np.int8)
    # Probability of occupancy: dark is occupied unless negate.
    occ = pixels / 255.0 if negate else (255.0 - pixels) / 255.0
    out = np.full(pixels.shape, UNKNOWN, dtype=np.int8)
    out[occ > occupied_thresh] = OCCUPIED
    out[occ < free_thresh] = FREE
    if mode == "scale":
        between = (occ >= free_thresh) & (occ <= occupied_thresh)
        scaled = 100 * (occ - free_thresh) / (occupied_thresh - free_thresh)
        out[between] = np.rint(scaled[between]).astype(np.int8)
        if alpha is not None:
            out[alpha < 255.0] = UNKNOWN
    return out


def read_image(path: Path) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64] | None]:
    """Grey levels 0..255 (channels averaged) and, when present, alpha 0..255."""
    suffix = path.suffix.lower()
    try:
        if suffix in (".pgm", ".pnm"):
            return read_pgm(path), None
        if suffix == ".png":
            return _read_png(path)
    except OSError as exc:
        raise MapError(f"{path}: cannot read map image: {exc}") from exc
    raise MapError(f"{path}: unsupported map image type {suffix!r} (use .pgm or .png)")


_PGM_TOKEN = re.compile(rb"(#[^\n]*\n)|(\s+)|([^\s#]+)")


def read_pgm(path: Path) -> npt.NDArray[np.float64]:
    """Read a PGM image (P5 binary 8/16 bit or P2 ASCII) as grey levels scaled to 0..255."""
    raw = path.read_bytes()
    header = width, height, maxval, start = _pgm_header(path, raw)
    if raw[:2] == b"P5":
        values = _p5_levels(path, raw, header).astype(np.float64)
    else:
        count = width * height
        try:
            values = np.array(raw[start:].split(), dtype=np.float64)
        except ValueError as exc:
            raise MapError(f"{path}: non-numeric PGM P2 data") from exc
        if values.size < count:
            raise MapError(f"{path}: PGM has {values.size} values, need {count}")
        values = values[:count].reshape(height, width)
    return values * (255.0 / maxval)


def _binary_pgm_levels(path: Path) -> tuple[npt.NDArray[np.unsignedinteger], int] | None:
    """A binary (P5) PGM's grey levels as stored (rows top first) and its maxval; None for
    any other image (``read_image`` reads those)."""
    if path.suffix.lower() not in (".pgm", ".pnm"):
        return None
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise MapError(f"{path}: cannot read map image: {exc}") from exc
    if raw[:2] != b"P5":
        return None
    header = _pgm_header(path, raw)
    return _p5_levels(path, raw, header), header[2]


def _pgm_header(path: Path, raw: bytes) -> tuple[int, int, int, int]:
    """A PGM's width, height and maxval, and where its data starts (P5: after the one
    whitespace byte that ends the header)."""
    magic = raw[:2]
    if magic not in (b"P5", b"P2"):
        raise MapError(f"{path}: not a PGM image (magic {magic!r}, expected P5 or P2)")
    tokens: list[bytes] = []
    pos = 2
    while len(tokens) < 3:
        match = _PGM_TOKEN.match(raw, pos)
        if match is None:
            raise MapError(f"{path}: truncated PGM header")
        pos = match.end()
        if match.group(3) is not None:
            tokens.append(match.group(3))
    try:
        width, height, maxval = (int(t) for t in tokens)
    except ValueError as exc:
        raise MapError(f"{path}: bad PGM header {tokens!r}") from exc
    if width <= 0 or height <= 0 or not 0 < maxval < 65536:
        raise MapError(f"{path}: bad PGM size {width}x{height} or maxval {maxval}")
    return width, height, maxval, pos + 1 if magic == b"P5" else pos


def _p5_levels(
    path: Path, raw: bytes, header: tuple[int, int, int, int]
) -> npt.NDArray[np.unsignedinteger]:
    """The grey levels of a P5 PGM (``header``: ``_pgm_header``'s), a view of ``raw``, 16
    bit when maxval > 255."""
    width, height, maxval, start = header
    count = width * height
    dtype = np.dtype(">u2") if maxval > 255 else np.dtype(np.uint8)
    have, need = max(0, len(raw) - start), count * dtype.itemsize
    if have < need:
        raise MapError(f"{path}: PGM data is {have} bytes, need {need}")
    levels: npt.NDArray[np.unsignedinteger] = np.frombuffer(
        raw, dtype=dtype, count=count, offset=start
    )
    return levels.reshape(height, width)


def _read_png(path: Path) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64] | None]:
    import matplotlib.image as mpimg  # imported lazily: only PNG maps need it

    try:
        img = np.asarray(mpimg.imread(path), dtype=np.float64)
    except (ValueError, SyntaxError) as exc:
        raise MapError(f"{path}: cannot decode PNG: {exc}") from exc
    if img.dtype.kind == "f" and img.max(initial=0.0) <= 1.0:
        img = img * 255.0
    if img.ndim == 2:
        return img, None
    alpha = img[..., 3] if img.shape[2] == 4 else None
    return img[..., :3].mean(axis=2) if img.shape[2] >= 3 else img[..., 0], alpha


def _require(header: dict[str, Any], key: str, path: Path) -> Any:
    if key not in header:
        raise MapError(f"{path}: missing required key {key!r}")
    return header[key]


def _negate(value: Any, path: Path) -> bool:
    """nav2 reads ``negate`` as an int and, failing that, as a bool: 0/1 and false/true."""
    if isinstance(value, bool):
        return value
    if isinstance(value, int) and value in (0, 1):
        return bool(value)
    raise MapError(f"{path}: negate must be 0 or 1 (or false/true), got {value!r}")


def _number(value: Any, key: str, path: Path) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise MapError(f"{path}: {key} must be a finite number, got {value!r}")
    return float(value)


# -- writing -------------------------------------------------------------------------------
def save_map(grid: OccupancyMap, yaml_path: str | Path, *, image_name: str | None = None) -> Path:
    """Write ``grid`` as a trinary map_server map (PGM P5 + YAML); returns the YAML path."""
    path = Path(yaml_path)
    image = image_name or path.with_suffix(".pgm").name
    # map_server's own saver: free 254, occupied 0, unknown 205.
    pixels = np.full(grid.data.shape, 205, dtype=np.uint8)
    pixels[grid.data == FREE] = 254
    pixels[grid.data >= 65] = 0
    write_pgm(path.parent / image, np.flipud(pixels))
    header = {
        "image": image,
        "mode": "trinary",
        "resolution": grid.resolution,
        "origin": [grid.origin_x, grid.origin_y, grid.origin_yaw],
        "negate": 0,
        "occupied_thresh": 0.65,
        "free_thresh": 0.196,  # so that 205 (unknown) reads back as unknown
    }
    path.write_text(yaml.safe_dump(header, sort_keys=False), encoding="utf-8")
    return path


def write_pgm(path: Path, pixels: npt.NDArray[np.uint8], *, ascii_p2: bool = False) -> None:
    """Write an 8-bit grey image (top row first) as PGM P5, or P2 when ``ascii_p2``."""
    height, width = pixels.shape
    if ascii_p2:
        rows = "\n".join(" ".join(str(int(v)) for v in row) for row in pixels)
        path.write_text(f"P2\n# AssistantX\n{width} {height}\n255\n{rows}\n", encoding="ascii")
    else:
        path.write_bytes(f"P5\n{width} {height}\n255\n".encode("ascii") + pixels.tobytes())
