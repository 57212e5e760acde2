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

import pytest
from _pytest.nodeid import coerce_node_id


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
