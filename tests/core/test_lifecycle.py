"""The one component lifecycle: idempotent start/stop, async with, tracked tasks."""

from __future__ import annotations

import asyncio

import pytest

from assistantx.core.lifecycle import Component


class Recorder(Component):
    """Counts its hooks; ``fail_start`` makes ``_start`` raise after spawning a task."""

    def __init__(self, *, fail_start: bool = False) -> None:
        super().__init__()
        self.starts = 0
        self.stops = 0
        self.fail_start = fail_start
        self.cancelled: list[str] = []

    async def _start(self) -> None:
        self.starts += 1
        await asyncio.sleep(0)  # a concurrent start() gets a chance to run here
        self.create_task(self.forever("at-start"), name="at-start")
        if self.fail_start:
            raise OSError("cannot connect")

    async def _stop(self) -> None:
        # Runs after the tasks ended: whatever they held is no longer in use.
        assert not self.tasks
        self.stops += 1

    async def forever(self, name: str) -> None:
        try:
            await asyncio.Event().wait()
        finally:
            self.cancelled.append(name)


async def test_a_second_start_and_a_second_stop_do_nothing() -> None:
    component = Recorder()
    await component.start()
    await component.start()
    assert (component.started, component.starts, len(component.tasks)) == (True, 1, 1)
    await component.stop()
    await component.stop()
    assert (component.started, component.stops) == (False, 1)


async def test_concurrent_starts_start_once() -> None:
    component = Recorder()
    await asyncio.gather(component.start(), component.start(), component.start())
    assert component.starts == 1 and len(component.tasks) == 1
    await component.stop()


async def test_stop_cancels_and_awaits_every_tracked_task() -> None:
    component = Recorder()
    await component.start()
    component.create_task(component.forever("later"), name="later")
    tasks = component.tasks
    await asyncio.sleep(0)  # both tasks are running
    await component.stop()
    assert all(task.done() for task in tasks)
    assert sorted(component.cancelled) == ["at-start", "later"]
    assert not component.tasks


async def test_a_finished_task_is_no_longer_tracked() -> None:
    component = Recorder()
    await component.start()
    done = component.create_task(asyncio.sleep(0), name="short")
    await done
    await asyncio.sleep(0)  # the done-callback runs
    assert done not in component.tasks
    await component.stop()


async def test_async_with_starts_and_stops_and_can_run_again() -> None:
    component = Recorder()
    async with component as entered:
        assert entered is component and component.started
        await asyncio.sleep(0)
    assert not component.started and component.cancelled == ["at-start"]
    async with component:
        assert component.starts == 2
    assert component.stops == 2


async def test_a_failed_start_stops_again_and_raises() -> None:
    component = Recorder(fail_start=True)
    with pytest.raises(OSError, match="cannot connect"):
        await component.start()
    assert not component.started and not component.tasks
    assert component.stops == 1


async def test_no_task_runs_on_a_stopped_component() -> None:
    component = Recorder()
    with pytest.raises(RuntimeError, match="not started"):
        component.create_task(component.forever("orphan"))
    assert not component.tasks
