"""Traffic among robots on one map: blocks of floor reserved while robots drive.

The live counterpart of ``nav.fleet.Reservations`` (which reserves time windows ahead, for
planning): here a robot that is about to drive claims, in one step, every block of the floor
its path sweeps (the path's points widened by ``clearance_m``), waits where it stands until
no other robot holds any of them, and then hands each block back as soon as it has passed
it. A standing robot holds the blocks under its footprint.

Why no deadlock can form among driving robots: a robot never holds some blocks of a path
while waiting for the rest (all or nothing, Coffman's hold-and-wait condition broken), and
while it drives it waits for nobody. Two robots crossing one narrow corridor from opposite
ends therefore take turns: whoever claims first drives through; the other starts once the
first has left the shared blocks. The one wait that remains is for a robot that *stands*
on the way (at a desk in a corridor, or at the same goal); it ends when that robot drives on,
and ``patience_s`` bounds it: past it the move fails with BlockedError naming the other robot,
and the instruction's own retry decides what next (``deadlocks`` counts these).

``separation`` keeps the smallest distance seen between two robots' true positions, so a
test or a benchmark can tell that they never touched.
"""

from __future__ import annotations

import asyncio
import math
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

import numpy as np

from assistantx.core.clock import Clock
from assistantx.core.errors import BlockedError
from assistantx.nav.geometry import FloatArray
from assistantx.nav.planner import resample_polyline

Block = tuple[int, int]


@dataclass(frozen=True)
class TrafficParams:
    block_m: float = 0.25  # side of one reservable block of floor
    clearance_m: float = 0.3  # robot radius plus a margin: blocks within this of the path
    # Standing robots are obstacles this wide to a robot that plans round them: wide enough
    # that the two footprints' blocks never touch.
    standing_radius_m: float = 0.9
    patience_s: float = 300.0  # longest wait behind a standing robot before giving up
    step_s: float = 0.25  # a driving robot moves and reports its position this often
    touch_m: float = 0.5  # robots whose centres come closer than this touch (2 radii)


class Traffic:
    def __init__(self, clock: Clock, params: TrafficParams | None = None) -> None:
        self.clock = clock
        self.params = params or TrafficParams()
        self._holder: dict[Block, str] = {}
        self._changed = asyncio.Event()
        self.positions: dict[str, tuple[float, float]] = {}
        self.driving: set[str] = set()  # robots between a claim and standing again
        self.separation_m = math.inf  # the closest two robots have been
        self.waits: list[tuple[str, float]] = []  # (robot, seconds it yielded) per claim
        self.deadlocks = 0  # waits that ran out of patience
        self.contacts = 0  # times two robots came closer than ``touch_m`` (collisions)
        self._touching: set[frozenset[str]] = set()

    # -- blocks ------------------------------------------------------------------------------
    def blocks_along(self, points: FloatArray) -> list[Block]:
        """The blocks within ``clearance_m`` of the polyline, in the order it reaches them."""
        seen: dict[Block, None] = {}
        for blocks in self._footprints(points):
            seen.update(dict.fromkeys(blocks))
        return list(seen)

    def _footprints(self, points: FloatArray) -> list[list[Block]]:
        """Per point of the polyline resampled at a quarter block: the blocks near it."""
        p = self.params
        dense = np.asarray(points, dtype=float)
        if len(dense) > 1:
            dense = resample_polyline(dense, p.block_m / 4)
        reach = math.ceil(p.clearance_m / p.block_m)
        out = []
        for x, y in dense:
            bx, by = math.floor(x / p.block_m), math.floor(y / p.block_m)
            out.append(
                [
                    (bx + dx, by + dy)
                    for dx in range(-reach, reach + 1)
                    for dy in range(-reach, reach + 1)
                    if self._gap(x, y, (bx + dx, by + dy)) <= p.clearance_m
                ]
            )
        return out

    def _gap(self, x: float, y: float, block: Block) -> float:
        """Distance from (x, y) to the nearest point of ``block``."""
        size = self.params.block_m
        x0, y0 = block[0] * size, block[1] * size
        dx = max(x0 - x, 0.0, x - (x0 + size))
        dy = max(y0 - y, 0.0, y - (y0 + size))
        return math.hypot(dx, dy)

    def holders(self, blocks: Iterable[Block], robot: str) -> set[str]:
        """The other robots holding any of ``blocks``."""
        return {h for b in blocks if (h := self._holder.get(b)) is not None and h != robot}

    # -- claims ------------------------------------------------------------------------------
    def stand(self, robot: str, x: float, y: float) -> None:
        """``robot`` stands at (x, y): it holds its footprint, and only that."""
        was_driving = robot in self.driving
        self.driving.discard(robot)
        self.keep(robot, set(self.blocks_along(np.array([[x, y]]))))
        self.moved(robot, x, y)
        if was_driving:  # robots waiting behind it may now go round it
            self._notify()

    async def claim(
        self,
        robot: str,
        path: FloatArray,
        detour: Callable[[list[tuple[float, float]]], FloatArray | None] | None = None,
    ) -> FloatArray:
        """Wait until no other robot holds a block of ``path``, then hold them all; returns
        the path claimed. When only standing robots are in the way, ``detour(their
        positions)`` may give a path round them (None: there is none, e.g. one stands on the
        goal), which is claimed instead. Raises BlockedError past ``patience_s``."""
        blocks = self.blocks_along(path)
        started = self.clock.timer()
        tried: set[tuple[str, tuple[float, float]]] = set()  # standing robots gone round
        while others := self.holders(blocks, robot):
            standing = {(o, self.positions.get(o, (math.nan, math.nan))) for o in others}
            if detour is not None and not others & self.driving and not standing <= tried:
                tried |= standing
                around = detour([xy for _, xy in sorted(standing)])
                if around is not None:
                    path, blocks = around, self.blocks_along(around)
                    continue
            waited = self.clock.timer() - started
            left = self.params.patience_s - waited
            if left <= 0:
                self.deadlocks += 1
                self.waits.append((robot, waited))
                raise BlockedError(
                    f"another robot ({', '.join(sorted(others))}) has stood in the way for "
                    f"{waited:.0f} s"
                )
            changed = self._changed
            await self.clock.wait_event(changed, left)
        for block in blocks:
            self._holder[block] = robot
        self.driving.add(robot)
        self.waits.append((robot, self.clock.timer() - started))
        return path

    def keep(self, robot: str, blocks: set[Block]) -> None:
        """``robot`` holds ``blocks`` (a subset of what it held) and hands the rest back."""
        gone = [b for b, h in self._holder.items() if h == robot and b not in blocks]
        for block in gone:
            del self._holder[block]
        for block in blocks:
            self._holder.setdefault(block, robot)
        if gone:
            self._notify()

    def leave(self, robot: str) -> None:
        """``robot`` is off the floor (stopped, or taken away): it holds nothing."""
        self.keep(robot, set())
        self.positions.pop(robot, None)
        self.driving.discard(robot)

    def _notify(self) -> None:
        changed, self._changed = self._changed, asyncio.Event()
        changed.set()

    # -- positions ---------------------------------------------------------------------------
    def moved(self, robot: str, x: float, y: float) -> None:
        self.positions[robot] = (x, y)
        for other, (ox, oy) in self.positions.items():
            if other == robot:
                continue
            gap = math.hypot(x - ox, y - oy)
            self.separation_m = min(self.separation_m, gap)
            pair = frozenset((robot, other))
            if gap < self.params.touch_m and pair not in self._touching:
                self.contacts += 1
                self._touching.add(pair)
            elif gap >= self.params.touch_m:
                self._touching.discard(pair)

    def drive(
        self, robot: str, points: FloatArray, speed_mps: float
    ) -> Iterator[tuple[float, float, float]]:
        """Walk the claimed path at ``speed_mps``: yields (x, y, seconds) every ``step_s``,
        having handed back the blocks the robot has fully passed."""
        dense = resample_polyline(np.asarray(points, dtype=float), speed_mps * self.params.step_s)
        # What the robot still needs from each point on: the union of the footprints ahead.
        ahead: list[set[Block]] = [set() for _ in dense]
        needed: set[Block] = set()
        for i in range(len(dense) - 1, -1, -1):
            end = dense[i : i + 2]
            for footprint in self._footprints(end):
                needed.update(footprint)
            ahead[i] = set(needed)
        for i in range(1, len(dense)):
            x, y = float(dense[i][0]), float(dense[i][1])
            seconds = float(np.hypot(*(dense[i] - dense[i - 1]))) / speed_mps
            self.keep(robot, ahead[i - 1])
            yield x, y, seconds
