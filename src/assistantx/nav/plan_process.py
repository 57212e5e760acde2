"""Planning in a worker process, so a long search never stalls the caller's event loop.

scipy's Dijkstra holds the GIL for the whole search: in a worker *thread* a plan across a
big building still stops the event loop for its length. ``PlanProcess`` runs the search in
one worker process (spawned, so no locks are inherited from the caller's threads) while the
calling thread waits with the GIL released.

A planner's costs cross over once per version: the worker keeps the planners it was sent,
keyed by the planner's ``token`` and ``version`` (``update_window`` bumps the version when
seen obstacles change the costs), and the caller sends the costs again only when the worker
does not have that version yet.
"""

from __future__ import annotations

import logging
import multiprocessing
import os
import pathlib
import signal
import threading
import time
from concurrent.futures import Future, ProcessPoolExecutor

import numpy as np
import numpy.typing as npt

from assistantx.nav import disk_cache
from assistantx.nav.costmap import Costmap, InflationParams
from assistantx.nav.occupancy_map import OccupancyMap
from assistantx.nav.planner import GridPlanner, Path, PlannerParams

logger = logging.getLogger(__name__)

_KEEP = 4  # planners the worker keeps (the map's, and a robot's latest layered versions)
_Key = tuple[str, int]
_Payload = tuple[
    OccupancyMap,
    npt.NDArray[np.uint8],
    InflationParams,
    PlannerParams,
    npt.NDArray[np.int32] | None,  # the components when the caller has them: not redone here
]
_worker_planners: dict[_Key, GridPlanner] = {}  # in the worker process only


_PARENT_CHECK_S = 0.5  # how often the worker looks whether the process that started it lives


def _start_worker(parent: int, cache: pathlib.Path | None) -> None:
    """The worker's initializer: it keeps derived arrays (the planners' landmarks) in the
    parent's map cache, and ends when its parent does."""
    disk_cache.use_directory(cache)
    _exit_with_parent(parent)


def _exit_with_parent(parent: int) -> None:
    """The worker ends when its parent does. A parent killed (SIGKILL, a crash) never shuts
    the pool down, and the worker, blocked on its call queue, lived on, with the resource
    tracker it holds open (8 of them after one killed test run)."""

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(_PARENT_CHECK_S)
        os._exit(0)

    threading.Thread(target=watch, name="exit-with-parent", daemon=True).start()


class _Missing(Exception):
    """The worker lacks this planner version: send its costs."""


def _keep_in_worker(key: _Key, payload: _Payload) -> None:
    if key not in _worker_planners:
        _worker_planners[key] = _planner_from(payload)


def _prepare_in_worker(key: _Key) -> None:
    """Measure a kept planner's landmarks now rather than on its first plan."""
    planner = _worker_planners.get(key)
    if planner is not None:
        planner.prepare()


def _plan_in_worker(
    key: _Key, payload: _Payload | None, start: tuple[float, float], goal: tuple[float, float]
) -> Path:
    planner = _worker_planners.get(key)
    if planner is None:
        if payload is None:
            raise _Missing(key)
        planner = _planner_from(payload)
        _worker_planners[key] = planner
        while len(_worker_planners) > _KEEP:
            del _worker_planners[next(iter(_worker_planners))]
    return planner.plan(start, goal)


class PlanProcess:
    """One worker process that plans for every caller in this process (one at a time)."""

    def __init__(self) -> None:
        self._pool: ProcessPoolExecutor | None = None
        self._worker_pid: int | None = None
        self._lock = threading.Lock()
        self._sent: set[_Key] = set()
        self._preparing: Future[None] | None = None  # the landmarks warm asked for
        self._stopping = False

    def plan(
        self, planner: GridPlanner, start: tuple[float, float], goal: tuple[float, float]
    ) -> Path:
        """``planner.plan(start, goal)``, computed in the worker; raises what it raises."""
        key = (planner.token, planner.version)
        with self._lock:
            pool = self._ensure_pool()
            payload = None if key in self._sent else _payload(planner)
            try:
                path = pool.submit(_plan_in_worker, key, payload, start, goal).result()
            except _Missing:
                path = pool.submit(_plan_in_worker, key, _payload(planner), start, goal).result()
            self._sent.add(key)
            return path

    def warm(self, planner: GridPlanner) -> None:
        """Start the worker and send it ``planner``'s costs now, so the first plan does not
        wait for a process to start (seconds on a busy machine)."""
        key = (planner.token, planner.version)
        with self._lock:
            if key not in self._sent:
                pool = self._ensure_pool()
                pool.submit(_keep_in_worker, key, _payload(planner)).result()
                self._sent.add(key)
                # The landmarks next, not waited for: the worker measures them (or reads
                # them from the map cache) before the first plan it is sent, while the
                # caller goes on starting.
                self._preparing = pool.submit(_prepare_in_worker, key)
                self._preparing.add_done_callback(self._log_failure)

    def close(self) -> None:
        """Stop the worker (a plan under way finishes first; queued ones are dropped). The
        next plan starts a new one. Landmarks still being measured are not waited for: the
        worker is ended (on a big map that measuring takes seconds, and a service stopped
        soon after its first start on a map waited for all of it: 3-6 s on nav2's warehouse
        against the 2 s a stop may take); only a plan's head start is lost."""
        with self._lock:
            if self._pool is not None:
                if self._preparing is not None and not self._preparing.done():
                    self._end_worker()
                self._pool.shutdown(wait=True, cancel_futures=True)
                self._pool = None
                self._stopping = False
                logger.info("stopped the planning worker process")
            self._sent.clear()
            self._preparing = None

    def _end_worker(self) -> None:
        self._stopping = True  # the preparation's failure is this stop, not a problem
        if self._worker_pid is None:
            return
        try:
            os.kill(self._worker_pid, signal.SIGTERM)
        except ProcessLookupError:  # it ended meanwhile
            return
        logger.info("ended the planning worker while it measured landmarks")

    def _log_failure(self, future: Future[None]) -> None:
        if future.cancelled() or self._stopping:  # stopped before or while it ran
            return
        error = future.exception()
        if error is not None:
            logger.warning("the planning worker could not prepare a planner: %r", error)

    def _ensure_pool(self) -> ProcessPoolExecutor:
        if self._pool is None:
            context = multiprocessing.get_context("spawn")
            self._pool = ProcessPoolExecutor(
                max_workers=1,
                mp_context=context,
                initializer=_start_worker,
                initargs=(os.getpid(), disk_cache.directory()),
            )
            # which process to end if a stop comes while it measures landmarks
            self._worker_pid = self._pool.submit(os.getpid).result()
            self._sent.clear()
            logger.info("started the planning worker process")
        return self._pool


def _payload(planner: GridPlanner) -> _Payload:
    costmap = planner.costmap
    # With a map cache (the worker shares the caller's) the worker reads the components
    # there, keyed by the costs it is sent, rather than get 4 bytes a cell through the pipe:
    # on nav2's warehouse 6.7 of the 10 MB the service pickled before it was ready.
    components = planner.known_components() if disk_cache.directory() is None else None
    return costmap.grid, costmap.costs.copy(), costmap.params, planner.params, components


def _planner_from(payload: _Payload) -> GridPlanner:
    grid, costs, inflation, params, components = payload
    costmap = Costmap(grid, costs, np.empty((0, 0)), inflation)
    # A robot's layered costs (the map's plus obstacles seen) keep the map planner's
    # landmarks: measuring them again for every version would cost a few full Dijkstras.
    marks = next(
        (
            kept.marks
            for kept in reversed(_worker_planners.values())
            if kept.params == params and kept.marks is not None and kept.marks.bounds(costs)
        ),
        None,
    )
    return GridPlanner(costmap, params, components=components, marks=marks or "measure")


PLAN_PROCESS = PlanProcess()
