"""One lifecycle for every component that talks to the outside (lock, robot, messenger, model).

A ``Component`` starts and stops idempotently (a second ``start`` or ``stop`` does nothing,
concurrent calls wait for the first), is an async context manager, and tracks the background
tasks it spawns with ``create_task``: ``stop`` cancels and awaits every one still running, so
nothing it started outlives it. Subclasses put their work in two hooks:

- ``_start()``: acquire resources, spawn tasks. ``started`` is already true while it runs (a
  message or request arriving mid-start is served, as it would be a moment later). If it
  raises, the component stops again (tasks cancelled, ``_stop`` called) and the error
  propagates, so ``_stop`` must cope with a half-done start.
- ``_stop()``: release what ``_start`` took. It runs after the tracked tasks are cancelled and
  awaited, so nothing is still using the resources it closes.

(python-telegram-bot's ``Application`` with its ``create_task`` is the model.)
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from collections.abc import Coroutine
from types import TracebackType
from typing import Any, Self, TypeVar

logger = logging.getLogger(__name__)

T = TypeVar("T")


async def cancel_and_wait(task: asyncio.Task[Any] | None) -> None:
    """Cancel a background task (None: there is none) and wait until it has ended; its
    CancelledError is the end asked for, not an error."""
    if task is None:
        return
    task.cancel()
    with contextlib.suppress(asyncio.CancelledError):
        await task


class Component:
    """Idempotent ``start``/``stop``, ``async with``, and tracked background tasks."""

    def __init__(self) -> None:
        self._started = False
        self._lifecycle_lock = asyncio.Lock()
        self._tasks: set[asyncio.Task[Any]] = set()

    @property
    def started(self) -> bool:
        return self._started

    @property
    def tasks(self) -> frozenset[asyncio.Task[Any]]:
        """The background tasks still running."""
        return frozenset(self._tasks)

    async def start(self) -> None:
        async with self._lifecycle_lock:
            if self._started:
                return
            self._started = True
            try:
                await self._start()
            except BaseException:
                await self._shut_down()
                raise

    async def stop(self) -> None:
        async with self._lifecycle_lock:
            if self._started:
                await self._shut_down()

    def create_task(
        self, coro: Coroutine[Any, Any, T], *, name: str | None = None
    ) -> asyncio.Task[T]:
        """Run ``coro`` in the background until it ends or the component stops."""
        if not self._started:
            coro.close()
            raise RuntimeError(f"{type(self).__name__} is not started")
        task = asyncio.create_task(coro, name=name)
        self._tasks.add(task)
        task.add_done_callback(self._task_done)
        return task

    async def __aenter__(self) -> Self:
        await self.start()
        return self

    async def __aexit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        await self.stop()

    async def _start(self) -> None:
        """Acquire resources and spawn background tasks. Called once per start."""

    async def _stop(self) -> None:
        """Release what ``_start`` acquired. Called once per stop, after the tasks ended."""

    async def _shut_down(self) -> None:
        self._started = False
        try:
            await self._cancel_tasks()
        finally:
            await self._stop()

    async def _cancel_tasks(self) -> None:
        tasks = list(self._tasks)
        for task in tasks:
            task.cancel()
        # A task that ignores its cancellation keeps stop() waiting: that is its bug to show.
        results = await asyncio.gather(*tasks, return_exceptions=True)
        for task, result in zip(tasks, results, strict=True):
            if isinstance(result, Exception):
                logger.error("%s: task %s had failed: %r", type(self).__name__, task, result)

    def _task_done(self, task: asyncio.Task[Any]) -> None:
        self._tasks.discard(task)
        if task.cancelled() or not self._started:
            return  # stop() collects it
        error = task.exception()
        if error is not None:
            logger.error(
                "%s: background task %s failed",
                type(self).__name__,
                task.get_name(),
                exc_info=error,
            )
