"""The ``xdist_group`` of a test, written into its id where ``--dist loadgroup`` looks for it.

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
    for item in items:
        group = group_of(item)
        if group is None or item.nodeid.endswith(f"@{group}"):
            continue
        # Parsed like any id, but its string form is the one given (with the suffix).
        item._id = coerce_node_id(f"{item.nodeid}@{group}")
