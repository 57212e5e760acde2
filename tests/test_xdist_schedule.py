"""Under `--dist loadgroup`, tests that share one worker carry their group in their id, where
xdist's controller (which sees ids, never markers) groups them, and the modules with a long test
are handed out first."""

from __future__ import annotations

import pytest
from xdist.scheduler.loadgroup import LoadGroupScheduling  # type: ignore[import-untyped]

from helpers.xdist_schedule import ModuleScheduling, long_modules_first, name_groups_in_ids

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


class _Worker:
    """What the scheduler uses of xdist's worker controller."""

    def __init__(self, name: str) -> None:
        self.gateway = type("Gateway", (), {"id": name})()
        self.shutting_down = False
        self.sent: list[list[int]] = []

    def send_runtest_some(self, indexes: list[int]) -> None:
        self.sent.append(list(indexes))

    def shutdown(self) -> None:
        self.shutting_down = True


def _config(pytester: pytest.Pytester, *args: str) -> pytest.Config:
    """A config of xdist's options only (no other plugin loaded: ~0.1 CPU-s, not ~0.2)."""
    return pytester.parseconfig(
        "-p", "xdist.plugin", "--tx", "2*popen", "--dist", "loadgroup", *args
    )


def test_whole_modules_and_groups_go_out_in_collection_order(
    pytester: pytest.Pytester, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("PYTEST_DISABLE_PLUGIN_AUTOLOAD", "1")
    ids = [
        "tests/test_b.py::test_b1",
        "tests/test_b.py::test_b2[x::y]",
        "tests/test_a.py::test_a1@synapse",
        "tests/test_c.py::test_c1",
        "tests/test_a.py::test_a2",
        "tests/test_d.py::test_d1@synapse",
        "tests/test_c.py::test_c2",
        "tests/test_c.py::test_c3",
        "tests/test_e.py::test_e1",
    ]
    fast = "not synapse and not browser and not llm_server and not postgres and not slow"
    config = _config(pytester, "-m", fast)
    scheduling = ModuleScheduling(config)
    assert [scheduling._split_scope(i) for i in ids[:3]] == [
        "tests/test_b.py",
        "tests/test_b.py",
        "synapse",
    ]
    one, two = _Worker("gw0"), _Worker("gw1")
    for worker in (one, two):
        scheduling.add_node(worker)
        scheduling.add_node_collection(worker, ids)
    scheduling.schedule()
    # In collection order and whole: test_b's two tests, the synapse group's (from two
    # modules), then each worker, with fewer than three waiting, one unit more: test_c's
    # three tests, test_a's test of no group.
    assert one.sent == [[0, 1], [3, 6, 7]]
    assert two.sent == [[2, 5], [4]]
    assert config.option.loadscopereorder  # the option is left as it was
    scheduling.mark_test_complete(one, 0)
    scheduling.mark_test_complete(one, 1)
    assert len(one.sent) == 2  # three still waiting: nothing more yet
    scheduling.mark_test_complete(one, 3)
    assert one.sent[-1] == [8]  # two waiting: the last unit
    scheduling.mark_test_complete(two, 2)
    assert two.shutting_down  # nothing left to hand out: it ends after what it holds
    for index in (6, 7, 8):
        scheduling.mark_test_complete(one, index)
    assert one.shutting_down
    assert all(all(unit.values()) for unit in scheduling.assigned_work[one].values())


def test_where_a_long_test_can_be_selected_each_test_of_no_group_goes_alone(
    pytester: pytest.Pytester, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("PYTEST_DISABLE_PLUGIN_AUTOLOAD", "1")
    for markexpr in ([], ["-m", "not synapse"], ["-m", "slow"]):
        scheduling = ModuleScheduling(_config(pytester, *markexpr))
        assert not scheduling.whole_modules
        assert scheduling._split_scope("tests/test_b.py::test_b1") == "tests/test_b.py::test_b1"
        assert scheduling._split_scope("tests/test_a.py::test_a1@synapse") == "synapse"
