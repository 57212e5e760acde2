"""The collector's full collections walk only what came since the last one; a thorough one
now and then walks everything again and frees the cycles among frozen objects.

Each case runs in an interpreter of its own, started for it (its heap: this module and what
it imports), as ``assistantx serve`` runs the collector in a process of its own: in a test
worker the heap holds every collected test of the run, which each of the cases' dozen full
collections walked (about 4 CPU-s for the module in `make test-fast`, 0.3 in a small heap)."""

from __future__ import annotations

import asyncio
import gc
import subprocess
import sys
import weakref
from collections.abc import Callable
from pathlib import Path
from typing import Any

from assistantx.service.collector import SurvivorFreezer

_TESTS = Path(__file__).parents[1]


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


def _in_an_interpreter_of_its_own(case: Callable[[_Clock], None]) -> None:
    """Runs ``case`` in a new interpreter where only the case's own collections run (the
    interpreter's are off) and nothing is frozen but what the case freezes; its assertion
    errors fail the test, with the case's traceback."""
    code = (
        f"import sys; sys.path.insert(0, {str(_TESTS)!r}); import gc; gc.disable(); "
        f"from service.test_collector import _Clock, {case.__name__} as case; "
        "assert gc.get_freeze_count() == 0; case(_Clock())"
    )
    ran = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=False
    )
    assert ran.returncode == 0, ran.stdout + ran.stderr


def test_survivors_are_frozen_and_a_thorough_collection_frees_their_cycles() -> None:
    _in_an_interpreter_of_its_own(_survivors_are_frozen_and_a_thorough_collection_frees_cycles)


def test_without_it_the_collector_frees_the_same_cycle() -> None:
    _in_an_interpreter_of_its_own(_without_it_the_collector_frees_the_same_cycle)


def test_paced_full_collections_run_on_the_loop_and_never_during_a_request() -> None:
    _in_an_interpreter_of_its_own(_paced_full_collections_run_on_the_loop_not_during_a_request)


def test_a_paced_collection_waits_for_requests_only_so_long() -> None:
    _in_an_interpreter_of_its_own(_a_paced_collection_waits_for_requests_only_so_long)


def _survivors_are_frozen_and_a_thorough_collection_frees_cycles(clock: _Clock) -> None:
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


def _without_it_the_collector_frees_the_same_cycle(clock: _Clock) -> None:
    held, member = _cycle()
    gc.collect()
    del held
    gc.collect()
    assert member() is None


def _paced_full_collections_run_on_the_loop_not_during_a_request(clock: _Clock) -> None:
    freezer = SurvivorFreezer(thorough_every_s=60.0, clock=clock)
    freezer.install()
    threshold = gc.get_threshold()
    in_flight = [1]  # a request is being answered
    loop = asyncio.new_event_loop()
    try:
        freezer.pace(loop, lambda: in_flight[0], pace_s=0.01, hold_max_s=3600.0)
        # The interpreter no longer starts full collections: the oldest generation's
        # threshold is out of reach, the younger ones are as they were.
        assert gc.get_threshold()[:2] == threshold[:2]
        assert gc.get_threshold()[2] > 1_000_000
        held, member = _cycle()
        del held
        # Due, but a request is in flight: the loop turns many times and does not collect.
        loop.run_until_complete(asyncio.sleep(0.1))
        assert freezer.paced_collections == 0
        assert member() is not None
        in_flight[0] = 0  # answered: the next look collects, on the loop, and freezes
        loop.run_until_complete(_full_collections(1))
        assert freezer.paced_collections == 1
        assert member() is None  # a full collection found the cycle
        assert freezer.frozen_collections == 1
        loop.run_until_complete(_full_collections(1))  # and again, a pace later
        assert freezer.paced_collections == 2
    finally:
        freezer.uninstall()
        loop.close()
    assert gc.get_threshold() == threshold  # uninstall gives the interpreter its own back


def _a_paced_collection_waits_for_requests_only_so_long(clock: _Clock) -> None:
    freezer = SurvivorFreezer(thorough_every_s=60.0, clock=clock)
    freezer.install()
    loop = asyncio.new_event_loop()
    try:
        freezer.pace(loop, lambda: 1, pace_s=0.01, hold_max_s=0.02)  # requests never stop
        loop.run_until_complete(_full_collections(2))
        assert freezer.paced_collections == 2
    finally:
        freezer.uninstall()
        loop.close()


async def _full_collections(count: int) -> None:
    """Returns once ``count`` more full collections have run (the pacer runs them on this
    loop's thread)."""
    ran, seen = asyncio.Event(), [0]

    def on_collection(phase: str, info: dict[str, Any]) -> None:
        if phase == "stop" and info["generation"] == 2:
            seen[0] += 1
            if seen[0] >= count:
                ran.set()

    gc.callbacks.append(on_collection)
    try:
        async with asyncio.timeout(30):  # a bound for a broken pacer, not a speed check
            await ran.wait()
    finally:
        gc.callbacks.remove(on_collection)
