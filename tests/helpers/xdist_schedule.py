"""How `--dist loadgroup` hands the tests out: each test's ``xdist_group`` written into its id,
where xdist looks for it, and the modules with a long test first.

xdist's controller never sees a test's markers, only the ids its workers collected: it groups
the tests whose id ends in the same ``@name``. xdist 3.8 appends that suffix by assigning
``item._nodeid``, which pytest 9.2 no longer reads (a node keeps its id as a ``NodeId`` in
``_id``), so every test went out on its own: Synapse and the llama.cpp server were started on
both workers and each `shares_worker` set-up was built twice. The suffix is written here
instead, once, after xdist's hook (on a pytest that still reads ``_nodeid`` it is already
there and left alone).
"""

from __future__ import annotations

from typing import Any

import pytest
from _pytest.nodeid import coerce_node_id
from xdist.scheduler.loadgroup import LoadGroupScheduling  # type: ignore[import-untyped]

from helpers.markers import never_selects


def group_of(item: pytest.Item) -> str | None:
    """The test's xdist group (several marks: their names joined, sorted, as xdist does)."""
    names = sorted(
        {str(mark.args[0] if mark.args else mark.kwargs.get("name", "default"))
         for mark in item.iter_markers("xdist_group")}
    )  # fmt: skip
    return "_".join(names) if names else None


def name_groups_in_ids(items: list[pytest.Item]) -> None:
    """Appends ``@group`` to the id of each grouped test that does not end in it yet."""
    for item in items:
        group = group_of(item)
        if group is None or item.nodeid.endswith(f"@{group}"):
            continue
        # Parsed like any id, but its string form is the one given (with the suffix).
        item._id = coerce_node_id(f"{item.nodeid}@{group}")


# The markers of the tests that start servers or processes, or localize on big maps: seconds
# to a minute each, where most others take milliseconds.
LONG_MARKERS = ("slow", "synapse", "browser", "llm_server", "postgres")


def long_modules_first(items: list[pytest.Item]) -> list[pytest.Item]:
    """The modules holding a long test first, each module's tests kept together and in order.

    xdist hands the tests out in this order, a few at a time, to whichever worker is free; a
    long test handed out last keeps one worker busy while the other has nothing left to do.
    Whole modules move, so a module's fixtures are still built once per worker.
    """
    long_modules = {
        item.path for item in items if any(item.get_closest_marker(m) for m in LONG_MARKERS)
    }
    return sorted(items, key=lambda item: item.path not in long_modules)


class ModuleScheduling(LoadGroupScheduling):  # type: ignore[misc]
    """`--dist loadgroup`, handing out whole modules where no long test can be selected.

    xdist's own makes each test of no group a unit of its own: the two workers took turns
    through every module, so each built a module's fixtures (a service, a parsed office, a
    reader) for the same module, and the controller, after each test, counted what a worker
    still had by walking every unit it had ever handed it (~11 M steps for 8,000 tests) and
    looked each test's index up in a list. Here, when `-m` deselects every long marker
    (`make test-fast`), a test of no group goes out with its module; otherwise (`make test`)
    each still goes out alone, so that two long tests of one module can run side by side.
    Units go out in collection order (the modules with a long test first,
    `long_modules_first`), not largest first, and the counts and indexes are kept as they
    change.
    """

    def __init__(self, config: pytest.Config, log: Any = None) -> None:
        super().__init__(config, log)
        markexpr = config.getoption("markexpr") or ""
        self.whole_modules = all(never_selects(markexpr, marker) for marker in LONG_MARKERS)
        self._pending_tests: dict[Any, int] = {}
        self._indexes: dict[Any, dict[str, int]] = {}

    def _split_scope(self, nodeid: str) -> str:
        scope: str = super()._split_scope(nodeid)
        if scope == nodeid and self.whole_modules:
            return nodeid.split("::", 1)[0]
        return scope

    def schedule(self) -> None:
        option = self.config.option
        reorder = option.loadscopereorder
        option.loadscopereorder = False  # keep the collection order
        try:
            super().schedule()
        finally:
            option.loadscopereorder = reorder

    def _assign_work_unit(self, node: Any) -> None:
        scope, work_unit = self.workqueue.popitem(last=False)
        self.assigned_work.setdefault(node, {})[scope] = work_unit
        index = self._indexes.get(node)
        if index is None:
            collection = self.registered_collections[node]
            index = self._indexes[node] = {nodeid: n for n, nodeid in enumerate(collection)}
        indexes = [index[nodeid] for nodeid, done in work_unit.items() if not done]
        self._pending_tests[node] = self._pending_tests.get(node, 0) + len(indexes)
        node.send_runtest_some(indexes)

    def mark_test_complete(self, node: Any, item_index: int, duration: float = 0) -> None:
        nodeid = self.registered_collections[node][item_index]
        self.assigned_work[node][self._split_scope(nodeid)][nodeid] = True
        self._pending_tests[node] -= 1
        self._reschedule(node)

    def _reschedule(self, node: Any) -> None:
        if node.shutting_down:
            return
        if not self.workqueue:
            node.shutdown()
            return
        if self._pending_tests.get(node, 0) > 2:  # xdist's heuristic: refill below three
            return
        self._assign_work_unit(node)

    def remove_node(self, node: Any) -> str | None:
        self._pending_tests.pop(node, None)
        self._indexes.pop(node, None)
        crashed: str | None = super().remove_node(node)
        return crashed
