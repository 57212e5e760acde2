"""AMCL groups its particles' histogram bins into connected clusters with its own small
union-find; the groups and their numbering are those of scipy's connected components."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from assistantx.nav.amcl import _connected_roots


def _scipy_labels(k: int, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    graph = coo_matrix((np.ones(a.size), (a, b)), shape=(k, k))
    return np.asarray(connected_components(graph, directed=False)[1])


def _ours(k: int, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    _, labels = np.unique(_connected_roots(k, a, b), return_inverse=True)
    return np.asarray(labels.reshape(-1))


@pytest.mark.parametrize("seed", range(20))
def test_random_graphs_group_as_scipy_does(seed: int) -> None:
    rng = np.random.default_rng(seed)
    k = int(rng.integers(1, 400))
    a, b = rng.integers(0, k, size=(2, int(rng.integers(0, 2 * k))))
    assert np.array_equal(_ours(k, a, b), _scipy_labels(k, a, b))


def test_a_long_chain_in_shuffled_order_is_one_group() -> None:
    order = np.random.default_rng(3).permutation(5000)
    labels = _ours(5000, order[:-1], order[1:])
    assert set(labels.tolist()) == {0}


def test_nodes_without_edges_are_groups_of_their_own() -> None:
    labels = _ours(4, np.array([2]), np.array([3]))
    assert labels.tolist() == [0, 1, 2, 2]
