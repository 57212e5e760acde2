"""The map's distance transforms are kept on disk by content hash: the same map reads them
back, another map or other parameters compute their own, a torn file is computed again."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from assistantx.nav import disk_cache
from assistantx.nav.amcl import AmclParams, LikelihoodField
from assistantx.nav.costmap import Costmap, InflationParams
from assistantx.nav.occupancy_map import OccupancyMap
from assistantx.nav.planner import GridPlanner


def _room(wall_at: int = 5) -> OccupancyMap:
    data = np.zeros((40, 60), dtype=np.int8)
    data[0, :] = data[-1, :] = data[:, 0] = data[:, -1] = 100
    data[wall_at, 10:50] = 100
    return OccupancyMap(data, 0.05, 0.0, 0.0, 0.0)


@pytest.fixture
def cache_dir(tmp_path: Path) -> Iterator[Path]:
    disk_cache.use_directory(tmp_path / "cache")
    try:
        yield tmp_path / "cache"
    finally:
        disk_cache.use_directory(None)


def test_a_second_costmap_on_the_same_map_reads_the_stored_distances(cache_dir: Path) -> None:
    first = Costmap.inflate(_room())
    [stored] = list(cache_dir.glob("obstacle-distance-*.npy"))
    stamp = stored.stat().st_mtime_ns
    second = Costmap.inflate(_room())
    assert stored.stat().st_mtime_ns == stamp  # read, not written again
    assert np.array_equal(second.obstacle_distance_m, first.obstacle_distance_m)
    assert np.array_equal(second.costs, first.costs)


def test_stored_distances_equal_computed_ones(cache_dir: Path) -> None:
    Costmap.inflate(_room())
    from_disk = Costmap.inflate(_room())
    disk_cache.use_directory(None)
    computed = Costmap.inflate(_room())
    assert np.array_equal(from_disk.costs, computed.costs)
    field_disk = (LikelihoodField(_room(), AmclParams()), LikelihoodField(_room(), AmclParams()))
    assert np.array_equal(field_disk[1].log_p, field_disk[0].log_p)


def test_another_map_or_radius_gets_its_own_file(cache_dir: Path) -> None:
    Costmap.inflate(_room(wall_at=5))
    Costmap.inflate(_room(wall_at=20))
    Costmap.inflate(_room(wall_at=5), InflationParams(inflation_radius=2.5))
    assert len(list(cache_dir.glob("obstacle-distance-*.npy"))) == 3


def test_a_torn_file_is_computed_again_and_replaced(cache_dir: Path) -> None:
    expected = Costmap.inflate(_room()).costs
    [stored] = list(cache_dir.glob("obstacle-distance-*.npy"))
    stored.write_bytes(stored.read_bytes()[:100])  # a crash mid-write by another tool
    assert np.array_equal(Costmap.inflate(_room()).costs, expected)
    assert np.array_equal(Costmap.inflate(_room()).costs, expected)  # and the file is whole


def test_without_a_directory_nothing_is_written(tmp_path: Path) -> None:
    Costmap.inflate(_room())
    assert list(tmp_path.iterdir()) == []


def test_the_planners_components_are_read_back_and_a_torn_file_recomputed(cache_dir: Path) -> None:
    costmap = Costmap.inflate(_room(wall_at=20))
    first = GridPlanner(costmap)
    [stored] = list(cache_dir.glob("traversable-components-*.npy"))
    stamp = stored.stat().st_mtime_ns
    second = GridPlanner(costmap)
    assert stored.stat().st_mtime_ns == stamp  # read, not written again
    assert np.array_equal(second.known_components(), first.known_components())
    stored.write_bytes(b"\x93NUMPY garbage")
    third = GridPlanner(costmap)
    assert np.array_equal(third.known_components(), first.known_components())
    disk_cache.use_directory(None)
    assert np.array_equal(GridPlanner(costmap).known_components(), first.known_components())


def test_another_map_gets_its_own_components(cache_dir: Path) -> None:
    GridPlanner(Costmap.inflate(_room(wall_at=5)))
    GridPlanner(Costmap.inflate(_room(wall_at=20)))
    assert len(list(cache_dir.glob("traversable-components-*.npy"))) == 2


def test_amcls_field_is_mapped_back_read_only_and_equals_the_computed_one(
    cache_dir: Path,
) -> None:
    first = LikelihoodField(_room(), AmclParams())
    stored = {f.name: f.stat().st_mtime_ns for f in cache_dir.glob("endpoint-*.npy")}
    assert {name.rsplit("-", 1)[0] for name in stored} == {
        "endpoint-distance",
        "endpoint-log-likelihood",
    }
    second = LikelihoodField(_room(), AmclParams())
    assert {f.name: f.stat().st_mtime_ns for f in cache_dir.glob("endpoint-*.npy")} == stored
    disk_cache.use_directory(None)
    computed = LikelihoodField(_room(), AmclParams())
    for field in (first, second, computed):
        assert np.array_equal(field.log_p, computed.log_p)
        assert np.array_equal(field.distance_m, computed.distance_m)
        with pytest.raises(ValueError, match="read-only"):  # computed or read, the same
            field.log_p[0] = 0.0


def test_another_map_or_beam_model_gets_a_field_of_its_own(cache_dir: Path) -> None:
    walled = LikelihoodField(_room(wall_at=20), AmclParams())
    other_map = LikelihoodField(_room(wall_at=5), AmclParams())
    assert len(list(cache_dir.glob("endpoint-distance-*.npy"))) == 2
    cell = 20 * 60 + 30  # on the wall of the first map, open floor in the second
    assert walled.distance_m[cell] == 0.0 < other_map.distance_m[cell]
    sharper = LikelihoodField(_room(wall_at=5), AmclParams(sigma_hit=0.05))
    assert len(list(cache_dir.glob("endpoint-distance-*.npy"))) == 2  # the same distances
    assert len(list(cache_dir.glob("endpoint-log-likelihood-*.npy"))) == 3
    assert not np.array_equal(sharper.log_p, other_map.log_p)


def test_the_costs_are_read_back_writable_and_kept_per_inflation(cache_dir: Path) -> None:
    first = Costmap.inflate(_room())
    [stored] = list(cache_dir.glob("inflation-costs-*.npy"))
    stamp = stored.stat().st_mtime_ns
    second = Costmap.inflate(_room())
    assert stored.stat().st_mtime_ns == stamp
    assert np.array_equal(second.costs, first.costs)
    second.costs[1, 1] = 0  # the obstacle layer writes into a copy; tests into the costs
    assert Costmap.inflate(_room()).costs[1, 1] == first.costs[1, 1]  # the file unchanged
    with pytest.raises(ValueError, match="read-only"):
        second.obstacle_distance_m[1, 1] = 0.0
    steeper = Costmap.inflate(_room(), InflationParams(cost_scaling_factor=3.0))
    assert len(list(cache_dir.glob("inflation-costs-*.npy"))) == 2
    assert len(list(cache_dir.glob("obstacle-distance-*.npy"))) == 1  # the same distances
    assert not np.array_equal(steeper.costs, first.costs)
