"""Under `--dist loadgroup`, tests that share one worker carry their group in their id, where
xdist's controller (which sees ids, never markers) groups them, and the modules with a long test
are handed out first."""

from __future__ import annotations

import pytest
from xdist.scheduler.loadgroup import LoadGroupScheduling  # type: ignore[import-untyped]

from helpers.xdist_schedule import long_modules_first, name_groups_in_ids

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


def test_modules_with_a_long_test_go_first_whole_and_in_order(
    pytester: pytest.Pytester, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("PYTEST_DISABLE_PLUGIN_AUTOLOAD", "1")
    pytester.makeini("[pytest]\nmarkers =\n    slow\n    synapse\n")
    pytester.makepyfile(
        test_a="def test_a1(): pass\ndef test_a2(): pass\n",
        test_b="import pytest\ndef test_b1(): pass\n@pytest.mark.slow\ndef test_b2(): pass\n",
        test_c="def test_c1(): pass\n",
        test_d="import pytest\npytestmark = pytest.mark.synapse\ndef test_d1(): pass\n",
    )
    items = pytester.inline_genitems()[0]
    assert [item.name for item in items] == [
        "test_a1",
        "test_a2",
        "test_b1",
        "test_b2",
        "test_c1",
        "test_d1",
    ]
    ordered = long_modules_first(items)
    assert [item.name for item in ordered] == [
        "test_b1",
        "test_b2",
        "test_d1",
        "test_a1",
        "test_a2",
        "test_c1",
    ]
