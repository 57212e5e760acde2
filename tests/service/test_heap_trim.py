"""The C heap's free pages go back to the system every TRIM_EVERY ended instructions (issue 26:
resident memory flat over 10,000 instructions)."""

from __future__ import annotations

import platform
from pathlib import Path

import pytest

from assistantx.service.heap_trim import TRIM_EVERY, HeapTrim, malloc_trim
from helpers.eventually import eventually
from helpers.instructions import ended as instruction_ended
from service.inprocess import serving_runtime
from service.server import LEE, OPERATOR

OP = {"Authorization": f"Bearer {OPERATOR}"}
AS_LEE = {"Authorization": f"Bearer {LEE}"}


class Trims:
    """Counts the trims asked for (the C call itself is glibc's)."""

    def __init__(self) -> None:
        self.calls = 0

    def __call__(self) -> None:
        self.calls += 1


async def test_the_heap_is_trimmed_at_every_nth_ended_instruction() -> None:
    trims = Trims()
    heap = HeapTrim(trims, every=3)
    seen = []
    for _ in range(7):
        await heap.on_end(object())
        seen.append(trims.calls)
    assert seen == [0, 0, 1, 1, 1, 2, 2]
    assert (heap.ended, heap.trims) == (7, 2)


async def test_the_default_period() -> None:
    trims = Trims()
    heap = HeapTrim(trims)
    for _ in range(TRIM_EVERY - 1):
        await heap.on_end(object())
    assert trims.calls == 0
    await heap.on_end(object())
    assert trims.calls == 1


async def test_without_malloc_trim_instructions_are_only_counted() -> None:
    heap = HeapTrim(None, every=1)
    await heap.on_end(object())
    assert (heap.ended, heap.trims) == (1, 0)


def test_glibc_malloc_trim_is_found_and_runs() -> None:
    trim = malloc_trim()
    if platform.libc_ver()[0] != "glibc":
        assert trim is None
        return
    assert trim is not None
    assert trim() in (0, 1)  # 1: memory was released, 0: there was none to release


def test_the_period_must_be_positive() -> None:
    with pytest.raises(ValueError, match="every"):
        HeapTrim(None, every=0)


async def test_the_service_counts_its_ended_instructions_for_the_trim(tmp_path: Path) -> None:
    # speed-up 200: only the end of the instruction is looked at
    async with serving_runtime(tmp_path / "data", speedup=200) as (api, runtime):
        r = await api.post(
            "/v1/instructions",
            json={"requester": "lee", "text": "Please bring me a stapler."},
            headers=AS_LEE,
        )
        await instruction_ended(api, r.json()["id"], OP)
        assert await eventually(lambda: runtime.heap_trim.ended == 1, what="the end counted")
        assert runtime.heap_trim.every == TRIM_EVERY
