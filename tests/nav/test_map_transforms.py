"""The compiled distance transform and components give scipy.ndimage's arrays exactly (the
map cache keeps either; a start on a new map needs no scipy), and without the extension
scipy computes the same."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import numpy.typing as npt
import pytest
from scipy.ndimage import distance_transform_edt, label

from assistantx.nav import map_transforms
from assistantx.nav.costmap import Costmap
from assistantx.nav.occupancy_map import load_map

ROOT = Path(__file__).resolve().parents[2]
REAL_MAPS = [ROOT / "maps" / "office.yaml", ROOT / "maps" / "nav2" / "tb3_sandbox.yaml"]


def _random_grids(count: int) -> list[npt.NDArray[np.bool_]]:
    """Grids of 1..47 cells a side, from empty to full (seeded)."""
    rng = np.random.default_rng(7)
    grids = []
    for _ in range(count):
        height, width = (int(n) for n in rng.integers(1, 48, 2))
        grids.append(rng.random((height, width)) < rng.random())
    return grids


GRIDS = _random_grids(50)


def test_the_extension_is_built_with_the_package() -> None:
    assert map_transforms.available()


@pytest.mark.parametrize("index", range(len(GRIDS)))
def test_distances_equal_scipys_on_random_grids(index: int) -> None:
    marked = GRIDS[index].copy()
    if not marked.any():  # scipy's transform needs one
        marked[0, -1] = True
    expected = distance_transform_edt(~marked)
    assert np.array_equal(map_transforms.distance_to(marked), expected)


@pytest.mark.parametrize("map_yaml", REAL_MAPS, ids=lambda p: p.stem)
def test_distances_and_components_equal_scipys_on_real_maps(map_yaml: Path) -> None:
    grid = load_map(map_yaml)
    occupied = grid.data >= 65
    assert np.array_equal(map_transforms.distance_to(occupied), distance_transform_edt(~occupied))
    traversable = Costmap.inflate(grid).traversable  # what the planner labels
    assert np.array_equal(map_transforms.components(traversable), label(traversable)[0])
    walls, count = label(occupied)  # many pieces: the numbering is checked too
    assert count > 1
    labels = map_transforms.components(occupied)
    assert labels.dtype == np.int32
    assert np.array_equal(labels, walls)


def test_a_map_with_no_marked_cell_is_infinitely_far_from_one() -> None:
    assert np.isinf(map_transforms.distance_to(np.zeros((3, 4), dtype=bool))).all()


def test_a_single_cell_and_a_single_line() -> None:
    assert map_transforms.distance_to(np.ones((1, 1), dtype=bool)).tolist() == [[0.0]]
    row = np.array([[False, False, True, False, False, False]])
    assert map_transforms.distance_to(row).tolist() == [[2.0, 1.0, 0.0, 1.0, 2.0, 3.0]]
    assert map_transforms.distance_to(row.T).ravel().tolist() == [2.0, 1.0, 0.0, 1.0, 2.0, 3.0]


@pytest.mark.parametrize("index", range(len(GRIDS)))
def test_components_equal_scipys_labels_on_random_grids(index: int) -> None:
    cells = GRIDS[index]
    expected, _ = label(cells)
    assert np.array_equal(map_transforms.components(cells), expected)


def test_components_touch_by_edges_only_and_are_numbered_by_first_cell() -> None:
    cells = np.array(
        [
            [0, 0, 1, 0],
            [1, 0, 1, 0],
            [0, 1, 0, 0],  # diagonal neighbours of both: a component of its own
            [1, 1, 0, 1],
        ],
        dtype=bool,
    )
    assert map_transforms.components(cells).tolist() == [
        [0, 0, 1, 0],
        [2, 0, 1, 0],
        [0, 3, 0, 0],
        [3, 3, 0, 4],
    ]


def test_without_the_extension_scipy_computes_the_same(monkeypatch: pytest.MonkeyPatch) -> None:
    grid = load_map(REAL_MAPS[0])
    occupied = grid.data >= 65
    compiled = (map_transforms.distance_to(occupied), map_transforms.components(~occupied))
    monkeypatch.setattr(map_transforms, "_library", lambda: None)
    assert not map_transforms.available()
    assert np.array_equal(map_transforms.distance_to(occupied), compiled[0])
    assert np.array_equal(map_transforms.components(~occupied), compiled[1])
    assert np.isinf(map_transforms.distance_to(np.zeros((2, 2), dtype=bool))).all()
