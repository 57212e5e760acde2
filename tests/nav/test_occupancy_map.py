"""Map loading in every map_server flavour, its error cases, and the committed office map."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

from assistantx.core.errors import MapError
from assistantx.nav.anchors import Anchor, load_anchors, save_anchors
from assistantx.nav.occupancy_map import (
    FREE,
    OCCUPIED,
    UNKNOWN,
    OccupancyMap,
    load_map,
    pixels_to_occupancy,
    read_pgm,
    save_map,
)
from assistantx.nav.planner import GridPlanner

from .conftest import FIXTURES, REPO


def _expected_trinary() -> np.ndarray:
    """The fixture layout as occupancy values, row 0 at the bottom."""
    img = np.full((8, 12), FREE, dtype=np.int8)
    img[0, :] = img[-1, :] = img[:, 0] = img[:, -1] = OCCUPIED
    img[2:4, 3:5] = OCCUPIED
    img[5, 8:10] = UNKNOWN
    img[6, 2] = UNKNOWN
    return np.flipud(img)


@pytest.mark.parametrize("name", ["nav2", "willow", "negated", "ascii", "png"])
def test_every_format_loads_to_the_same_grid(name: str) -> None:
    grid = load_map(FIXTURES / f"{name}.yaml")
    np.testing.assert_array_equal(grid.data, _expected_trinary())


def test_header_fields_and_flip() -> None:
    grid = load_map(FIXTURES / "willow.yaml")
    assert (grid.resolution, grid.origin_x, grid.origin_y) == (0.1, -5.0, -3.0)
    assert (grid.width, grid.height) == (12, 8)
    # The block sits in image rows 2-3 (from the top) = grid rows 4-5 (from the bottom).
    assert grid.data[4, 3] == OCCUPIED
    assert grid.data[2, 3] == FREE
    # World point at the centre of cell (ix=3, iy=4).
    ix, iy = grid.world_to_cell(-5.0 + 0.35, -3.0 + 0.45)
    assert (int(ix), int(iy)) == (3, 4)
    assert grid.is_free(-5.0 + 0.55, -3.0 + 0.25)
    assert not grid.is_free(-5.0 + 0.35, -3.0 + 0.45)
    assert not grid.is_free(100.0, 0.0)


def test_scale_mode_keeps_grey_levels() -> None:
    grid = load_map(FIXTURES / "scale.yaml")
    # Grey 128: occupancy (255-128)/255 = 0.498 -> nav2 map_server's
    # rint(100 * (0.498-0.196)/(0.65-0.196)) = rint(66.5) = 67.
    assert grid.data[1, 2] == 67
    assert grid.data[0, 0] == OCCUPIED
    assert grid.data[3, 3] == FREE


def test_raw_mode_reads_values(tmp_path: Path) -> None:
    (tmp_path / "raw.pgm").write_bytes(b"P5\n5 1\n255\n" + bytes([0, 100, 205, 254, 42]))
    (tmp_path / "raw.yaml").write_text(
        "image: raw.pgm\nmode: raw\nresolution: 1\norigin: [0, 0, 0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n"
    )
    grid = load_map(tmp_path / "raw.yaml")
    # nav2: a grey level 0..100 is the value; anything else (the saver's 205 unknown and
    # 254 free) is unknown, never occupied.
    assert grid.data.tolist() == [[0, 100, UNKNOWN, UNKNOWN, 42]]


def test_sixteen_bit_pgm(tmp_path: Path) -> None:
    values = np.array([[0, 65535]], dtype=">u2")
    (tmp_path / "m.pgm").write_bytes(b"P5\n2 1\n65535\n" + values.tobytes())
    (tmp_path / "m.yaml").write_text(
        "image: m.pgm\nresolution: 0.5\norigin: [0, 0, 0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n"
    )
    assert load_map(tmp_path / "m.yaml").data.tolist() == [[OCCUPIED, FREE]]


@pytest.mark.parametrize("mode", ["trinary", "scale", "raw"])
@pytest.mark.parametrize("negate", [0, 1])
@pytest.mark.parametrize(("maxval", "dtype"), [(255, np.uint8), (1000, ">u2"), (65535, ">u2")])
def test_a_binary_pgm_converts_every_grey_level_as_its_pixels_would(
    tmp_path: Path, mode: str, negate: int, maxval: int, dtype: str
) -> None:
    """load_map converts each grey level once and looks the pixels up: every level (past
    maxval too) gives what converting that pixel gives, in every mode."""
    top = 255 if maxval == 255 else 65535
    rng = np.random.default_rng(maxval + negate)
    levels = np.concatenate([np.arange(top + 1), rng.integers(0, top + 1, 500)])
    levels = levels[: len(levels) // 4 * 4].reshape(4, -1).astype(dtype)
    height, width = levels.shape
    image = tmp_path / "m.pgm"
    image.write_bytes(f"P5\n{width} {height}\n{maxval}\n".encode() + levels.tobytes())
    (tmp_path / "m.yaml").write_text(
        f"image: m.pgm\nmode: {mode}\nresolution: 0.5\norigin: [0, 0, 0]\n"
        f"negate: {negate}\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
    )
    per_pixel = pixels_to_occupancy(
        read_pgm(image),
        None,
        negate=bool(negate),
        occupied_thresh=0.65,
        free_thresh=0.196,
        mode=mode,  # type: ignore[arg-type]
    )
    loaded = load_map(tmp_path / "m.yaml").data
    assert loaded.dtype == np.int8 and loaded.flags.c_contiguous
    np.testing.assert_array_equal(loaded, np.flipud(per_pixel))
    assert len(np.unique(loaded)) > 2  # the levels spread over free, unknown and occupied


def test_save_and_load_round_trip(tmp_path: Path) -> None:
    original = load_map(FIXTURES / "nav2.yaml")
    save_map(original, tmp_path / "copy.yaml")
    again = load_map(tmp_path / "copy.yaml")
    np.testing.assert_array_equal(again.data, original.data)
    assert (again.origin_x, again.origin_y, again.resolution) == (-1.0, -2.0, 0.05)


def _write_header(tmp_path: Path, **changes: object) -> Path:
    header: dict[str, object] = yaml.safe_load((FIXTURES / "nav2.yaml").read_text())
    header["image"] = str(FIXTURES / "nav2.pgm")
    header.update(changes)
    header = {k: v for k, v in header.items() if v is not None}
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(header))
    return path


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"resolution": None}, "missing required key 'resolution'"),
        ({"resolution": "fine"}, "resolution must be a finite number"),
        ({"resolution": 0}, "resolution must be positive"),
        ({"mode": "fancy"}, "mode must be one of"),
        ({"origin": [0, 0]}, "origin must be a list"),
        ({"negate": 2}, "negate must be 0 or 1"),
        ({"negate": "yes"}, "negate must be 0 or 1"),
        ({"free_thresh": 0.9}, "free_thresh < occupied_thresh"),
        ({"image": "nowhere.pgm"}, "cannot read map image"),
        ({"image": "map.jpg"}, "unsupported map image type"),
        ({"origin": [0, 0, "north"]}, "origin must be a finite number"),
    ],
)
def test_bad_headers_name_the_file_and_problem(
    tmp_path: Path, changes: dict[str, object], message: str
) -> None:
    path = _write_header(tmp_path, **changes)
    with pytest.raises(MapError, match=message) as info:
        load_map(path)
    named = str(changes.get("image", path.name))
    assert named in str(info.value)


@pytest.mark.parametrize(
    ("content", "message"),
    [
        (b"P6\n2 1\n255\nabcdef", "not a PGM image"),
        (b"P5\n4 4\n255\n" + bytes(3), "PGM data is 3 bytes, need 16"),
        (b"P5\n4", "truncated PGM header"),
        (b"P5\nfour 4 255\n", "bad PGM header"),
        (b"P2\n2 2\n255\n1 2 3\n", "PGM has 3 values, need 4"),
    ],
)
def test_bad_images(tmp_path: Path, content: bytes, message: str) -> None:
    (tmp_path / "m.pgm").write_bytes(content)
    path = _write_header(tmp_path, image=str(tmp_path / "m.pgm"))
    with pytest.raises(MapError, match=message):
        load_map(path)


def test_not_yaml(tmp_path: Path) -> None:
    path = tmp_path / "m.yaml"
    path.write_text("image: [unclosed\n")
    with pytest.raises(MapError, match="cannot read map header"):
        load_map(path)
    with pytest.raises(MapError, match="cannot read map header"):
        load_map(tmp_path / "absent.yaml")


def test_anchors_round_trip_and_errors(tmp_path: Path) -> None:
    save_anchors({"a": Anchor(1.0, 2.0, 0.5)}, tmp_path / "a.yaml")
    assert load_anchors(tmp_path / "a.yaml") == {"a": Anchor(1.0, 2.0, 0.5)}
    (tmp_path / "b.yaml").write_text("anchors:\n  a: {x: 1}\n")
    with pytest.raises(MapError, match="anchor 'a' needs x and y"):
        load_anchors(tmp_path / "b.yaml")
    (tmp_path / "c.yaml").write_text("anchors:\n  a: {x: one, y: 2}\n")
    with pytest.raises(MapError, match="non-numeric"):
        load_anchors(tmp_path / "c.yaml")
    (tmp_path / "d.yaml").write_text("- a\n")
    with pytest.raises(MapError, match="'anchors' mapping"):
        load_anchors(tmp_path / "d.yaml")


# -- the committed office map ----------------------------------------------------------------
def test_office_map_size(office_map: OccupancyMap) -> None:
    assert office_map.size_m == pytest.approx((40.0, 25.0))
    assert office_map.resolution == 0.05
    share_free = float(np.mean(office_map.data == FREE))
    assert 0.6 < share_free < 0.95


def test_anchors_match_the_office_and_are_reachable(
    office_map: OccupancyMap, office_anchors: dict[str, Anchor], office_planner: GridPlanner
) -> None:
    office = yaml.safe_load((REPO / "dataset" / "office.yaml").read_text())
    locations = {loc["id"]: (loc["x"], loc["y"]) for loc in office["locations"]}
    assert set(office_anchors) == set(locations)
    for name, (x, y) in locations.items():
        assert (office_anchors[name].x, office_anchors[name].y) == (x, y)
    first = next(iter(office_anchors.values()))
    paths = office_planner.plan_many(
        (first.x, first.y), [(a.x, a.y) for a in office_anchors.values()]
    )
    for name, path in zip(office_anchors, paths, strict=True):
        assert path is not None, f"{name} unreachable"
        a = office_anchors[name]
        assert path.length_m >= math.hypot(a.x - first.x, a.y - first.y) - 1e-9


def test_generator_reproduces_the_committed_map(tmp_path: Path, office_map: OccupancyMap) -> None:
    from assistantx.nav.office_map_gen import generate

    generate(tmp_path, REPO / "dataset" / "office.yaml")
    np.testing.assert_array_equal(load_map(tmp_path / "office.yaml").data, office_map.data)
    assert (tmp_path / "office.anchors.yaml").read_text() == (
        REPO / "maps" / "office.anchors.yaml"
    ).read_text()


def test_grid_validation() -> None:
    with pytest.raises(MapError, match="non-empty 2D"):
        OccupancyMap(np.zeros((0, 3), dtype=np.int8), 0.05)


@pytest.mark.parametrize(("negate", "same_as"), [(False, "nav2"), (True, "negated")])
def test_boolean_negate_is_read_as_map_server_does(
    tmp_path: Path, negate: bool, same_as: str
) -> None:
    header = yaml.safe_load((FIXTURES / f"{same_as}.yaml").read_text())
    header["image"] = str(FIXTURES / header["image"])
    header["negate"] = negate
    path = tmp_path / "m.yaml"
    path.write_text(yaml.safe_dump(header))
    np.testing.assert_array_equal(load_map(path).data, load_map(FIXTURES / f"{same_as}.yaml").data)


def test_origin_yaw_turns_the_grid_about_its_lower_left_corner(tmp_path: Path) -> None:
    header = yaml.safe_load((FIXTURES / "willow.yaml").read_text())
    header["image"] = str(FIXTURES / header["image"])
    header["origin"] = [1.0, 2.0, math.pi / 2]
    path = tmp_path / "turned.yaml"
    path.write_text(yaml.safe_dump(header))
    grid = load_map(path)
    assert grid.origin_yaw == pytest.approx(math.pi / 2)
    # With the grid turned by 90 degrees, its x axis points along world +y: the centre of
    # cell (ix=3, iy=4) lies at origin + (-(4.5) * 0.1, 3.5 * 0.1).
    x, y = grid.cell_to_world(3, 4)
    assert (float(x), float(y)) == pytest.approx((1.0 - 0.45, 2.0 + 0.35))
    ix, iy = grid.world_to_cell(x, y)
    assert (int(ix), int(iy)) == (3, 4)
    assert grid.data[4, 3] == OCCUPIED and not grid.is_free(float(x), float(y))
    # The LiDAR sees the turned walls: a beam from the cell centre (2, 2) towards the
    # block at cells x 3-4 along the grid's +x (world +y) ends at its near face.
    from assistantx.nav.lidar import cast_rays

    sx, sy = grid.cell_to_world(1.5, 4.5)
    ranges = cast_rays(
        grid.obstacles, grid, np.array([float(sx), float(sy), math.pi / 2]), np.array([0.0]), 5.0
    )
    assert ranges[0] == pytest.approx(0.1, abs=0.03)
