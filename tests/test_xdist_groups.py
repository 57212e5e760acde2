"""Tests that share one worker under `--dist loadgroup` carry their group in their id, where
xdist's controller (which sees ids, never markers) groups them."""

from __future__ import annotations

import pytest
from xdist.scheduler.loadgroup import LoadGroupScheduling  # type: ignore[import-untyped]

from helpers.xdist_groups import name_groups_in_ids

pytest_plugins = ["pytester"]

_TESTS = """
import pytest

@pytest.mark.xdist_group("synapse")
def test_one():
    pass

@pytest.mark.xdist_group(name="b")
@pytest.mark.xdist_group("a")
@pytest.mark.parametrize("n", ["x@y", "z"])
def test_two(n):
    pass

def test_three():
    pass
"""


def _scopes(items: list[pytest.Item]) -> list[str]:
    # the controller's own reading of an id (a method that uses nothing of its instance)
    return [LoadGroupScheduling._split_scope(None, item.nodeid) for item in items]


def test_each_grouped_test_id_names_its_group_once(
    pytester: pytest.Pytester, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("PYTEST_DISABLE_PLUGIN_AUTOLOAD", "1")  # collecting needs none of them
    pytester.makeini("[pytest]\nmarkers = xdist_group\n")
    items = pytester.getitems(_TESTS)
    name_groups_in_ids(items)
    name_groups_in_ids(items)  # a second pass (or xdist's own, where it works) adds nothing
    assert [item.nodeid.partition("::")[2] for item in items] == [
        "test_one@synapse",
        "test_two[x@y]@a_b",
        "test_two[z]@a_b",
        "test_three",
    ]
    assert _scopes(items)[:3] == ["synapse", "a_b", "a_b"]
    assert _scopes(items)[3].endswith("::test_three")  # on its own
