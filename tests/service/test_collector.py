"""The collector's full collections walk only what came since the last one; a thorough one
now and then walks everything again and frees the cycles among frozen objects."""

from __future__ import annotations

import gc
import weakref
from collections.abc import Iterator

import pytest

from assistantx.service.collector import SurvivorFreezer


class _Node:
    def __init__(self) -> None:
        self.other: _Node | None = None


def _cycle() -> tuple[_Node, weakref.ref[_Node]]:
    a, b = _Node(), _Node()
    a.other, b.other = b, a
    return a, weakref.ref(b)


class _Clock:
    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        return self.now


@pytest.fixture
def clock() -> Iterator[_Clock]:
    enabled = gc.isenabled()
    frozen = gc.get_freeze_count() > 0  # what the test process froze (tests/conftest.py)
    gc.disable()  # only the test's own collections run
    gc.unfreeze()  # and nothing is frozen but what the test freezes
    try:
        yield _Clock()
    finally:
        gc.unfreeze()  # the test process's heap as it was: its start-up frozen again
        if frozen:
            gc.freeze()
        if enabled:
            gc.enable()


def test_survivors_are_frozen_and_a_thorough_collection_frees_their_cycles(clock: _Clock) -> None:
    freezer = SurvivorFreezer(thorough_every_s=60.0, clock=clock)
    freezer.install()
    try:
        held, member = _cycle()
        gc.collect()  # survived (still referenced): frozen
        assert freezer.frozen_collections == 1
        assert gc.get_freeze_count() > 0
        del held  # now garbage, a cycle among frozen objects
        gc.collect()
        assert member() is not None  # out of the full collection's walk
        gc.collect(1)  # a younger collection freezes nothing
        assert freezer.frozen_collections == 2
        clock.now = 60.0
        gc.collect()  # thorough: unfreezes first, walks everything
        assert member() is None
        assert freezer.thorough_collections == 1
        assert gc.get_freeze_count() > 0  # its survivors frozen again
    finally:
        freezer.uninstall()


def test_without_it_the_collector_frees_the_same_cycle(clock: _Clock) -> None:
    held, member = _cycle()
    gc.collect()
    del held
    gc.collect()
    assert member() is None
