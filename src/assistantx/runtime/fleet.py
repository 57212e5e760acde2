"""Several robot bases, each with its own locker, serving one office's instructions.

The single robot's ``BodyLease`` becomes a lease per robot: an instruction that first needs
a body (a move, a QR code, a hand-over) is given one robot with its locker, and holds that
one until it ends; every drive, code and hand-over of the instruction then goes to it.

Which robot (Open-RMF's task allocation: the robot that would finish soonest): a robot that
is free now finishes sooner than one that is busy, whose end nobody can know (an instruction
waits for people), so a free robot always wins, and among free robots the one with the
shortest drive to where the instruction goes first (``toward``, measured on the map). With
none free, the instruction queues, and the first robot to come free serves the head of the
queue. A freed robot nobody waits for drives back to its own parking place, off the aisles,
and an instruction given it meanwhile stops that drive where it is.

Routing: the chosen robot is remembered in a context variable of the instruction's task
(asyncio gives each task its own context), so ``FleetRobot`` and ``FleetLocker`` -- the one
robot and the one locker the executors see -- act on that instruction's robot without the
executors knowing there are several. Outside an instruction (the dashboard's view, the
start) they show the first robot.
"""

from __future__ import annotations

import asyncio
import logging
from collections import deque
from collections.abc import Callable, Collection, Sequence
from contextvars import ContextVar
from dataclasses import dataclass, field

from assistantx.core.errors import AssistantXError
from assistantx.core.lifecycle import cancel_and_wait
from assistantx.core.ports.lock import Locker, LockEvent, LockStatus, Purpose, QRCode
from assistantx.core.ports.robot import MoveResult, RobotBase, RobotState

logger = logging.getLogger(__name__)


@dataclass
class Body:
    """One robot base and the locker it carries."""

    name: str  # as people read it: "robot 2"
    robot: RobotBase
    locker: Locker
    parking: str | None = None  # where it waits when nobody needs it (a location id)
    served: int = 0  # instructions it has been given
    _parking_drive: asyncio.Task[None] | None = field(default=None, repr=False)


RETURN_SUFFIX = ".return"  # runtime.returns: the errand that gives back what an instruction left
SERVED_KEPT = 256

_CURRENT: ContextVar[Body | None] = ContextVar("assistantx_fleet_body", default=None)


class FleetLease:
    """The lease per robot (the ``BodyLease`` interface, plus which robot each holds)."""

    def __init__(self, bodies: Sequence[Body], speed_mps: float = 0.5) -> None:
        if not bodies:
            raise ValueError("a fleet needs at least one robot")
        self.bodies = list(bodies)
        self.speed_mps = speed_mps
        self._holding: dict[str, Body] = {}  # instruction id → its robot
        # Waiting instructions in order, each with the one robot it must have (None: any).
        self._waiting: deque[tuple[str, Body | None, asyncio.Future[Body]]] = deque()
        # The robot each recent instruction had: its give-back errand ("<id>.return") needs
        # the same robot, whose locker holds what is to go back.
        self._served: dict[str, Body] = {}

    # -- what the service shows ------------------------------------------------------------
    @property
    def holder(self) -> str | None:
        """The instruction holding the first robot (what one robot's view shows)."""
        return self.holder_of(self.bodies[0])

    def holder_of(self, body: Body) -> str | None:
        return next((i for i, b in self._holding.items() if b is body), None)

    def body_of(self, instruction_id: str) -> Body | None:
        return self._holding.get(instruction_id)

    def queue(self) -> list[str]:
        """The holders first, then the waiting instructions in order."""
        return list(self._holding) + [iid for iid, _, _ in self._waiting]

    def holds(self, instruction_id: str) -> bool:
        body = self._holding.get(instruction_id)
        if body is not None:
            _CURRENT.set(body)  # a resumed task's context learns its robot again
        return body is not None

    # -- taking and giving back ------------------------------------------------------------
    async def acquire(
        self,
        instruction_id: str,
        on_wait: Callable[[list[str]], None] | None = None,
        toward: str | None = None,
    ) -> None:
        """Give ``instruction_id`` a robot: the free one that gets to ``toward`` (a location
        id) soonest; else wait for the first that comes free."""
        if self.holds(instruction_id):
            return
        needed = self._served.get(instruction_id.removesuffix(RETURN_SUFFIX))
        if not instruction_id.endswith(RETURN_SUFFIX):
            needed = None
        free = [b for b in self.bodies if self.holder_of(b) is None]
        if needed is not None:
            free = [b for b in free if b is needed]
        if free and not any(w is None or w in free for _, w, _ in self._waiting):
            body = min(free, key=lambda b: self._drive_s(b, toward))
        else:
            future: asyncio.Future[Body] = asyncio.get_running_loop().create_future()
            self._waiting.append((instruction_id, needed, future))
            if on_wait is not None:
                on_wait(self.queue())
            try:
                body = await future
            except asyncio.CancelledError:
                self._waiting = deque(w for w in self._waiting if w[2] is not future)
                if future.done() and not future.cancelled():
                    self._holding[instruction_id] = future.result()
                    self.release(instruction_id)
                raise
        self._holding[instruction_id] = body
        self._served[instruction_id] = body
        while len(self._served) > SERVED_KEPT:
            self._served.pop(next(iter(self._served)))
        body.served += 1
        _CURRENT.set(body)
        await self._stop_parking(body)
        logger.info("%s serves instruction %s", body.name, instruction_id)

    def release(self, instruction_id: str) -> None:
        body = self._holding.pop(instruction_id, None)
        if body is None:
            self._waiting = deque(w for w in self._waiting if w[0] != instruction_id)
            return
        for waiter in list(self._waiting):
            next_id, needed, future = waiter
            if future.done():
                self._waiting.remove(waiter)
            elif needed is None or needed is body:
                self._waiting.remove(waiter)
                self._holding[next_id] = body
                future.set_result(body)
                return
        self._park(body)

    def _drive_s(self, body: Body, toward: str | None) -> float:
        """Seconds ``body`` needs to reach ``toward`` (0 when unknown: any robot will do)."""
        here = body.robot.state().place
        if toward is None or here is None or here == toward:
            return 0.0
        try:
            metres = body.robot.path_length(here, toward)
        except AssistantXError:
            return float("inf")
        return 0.0 if metres is None else metres / self.speed_mps

    # -- parking ---------------------------------------------------------------------------
    def _park(self, body: Body) -> None:
        """Nobody needs ``body``: it drives to its parking place, off the others' way."""
        if body.parking is None or body.robot.state().place == body.parking:
            return
        body._parking_drive = asyncio.get_running_loop().create_task(
            self._drive_to_parking(body), name=f"{body.name} parks"
        )

    async def _drive_to_parking(self, body: Body) -> None:
        assert body.parking is not None
        try:
            await body.robot.move_to(body.parking)
        except AssistantXError as exc:
            logger.warning("%s could not drive to its parking place: %s", body.name, exc)

    async def _stop_parking(self, body: Body) -> None:
        drive, body._parking_drive = body._parking_drive, None
        if drive is not None and not drive.done():
            await cancel_and_wait(drive)

    async def stop(self) -> None:
        """Stop every parking drive (the service stops)."""
        for body in self.bodies:
            await self._stop_parking(body)


def current_body(bodies: Sequence[Body]) -> Body:
    """The robot of the instruction running in this task; the first one elsewhere."""
    return _CURRENT.get() or bodies[0]


class FleetRobot(RobotBase):
    """The one robot base the executors see: each call goes to the calling instruction's
    robot. ``places``: the office's location ids; a robot standing anywhere else (a parking
    place) is, to the instructions, at no place of the office (``place`` None)."""

    def __init__(self, bodies: Sequence[Body], places: Collection[str]) -> None:
        super().__init__()
        self.bodies = list(bodies)
        self.places = frozenset(places)

    async def _start(self) -> None:
        for body in self.bodies:
            await body.robot.start()

    async def _stop(self) -> None:
        for body in reversed(self.bodies):
            await body.robot.stop()

    async def move_to(self, location_id: str) -> MoveResult:
        return await current_body(self.bodies).robot.move_to(location_id)

    def state(self) -> RobotState:
        state = current_body(self.bodies).robot.state()
        if state.place is not None and state.place not in self.places:
            return state.model_copy(update={"place": None})
        return state

    def path_length(self, a: str, b: str) -> float | None:
        return self.bodies[0].robot.path_length(a, b)  # one floor map for all

    def forget_obstacles(self) -> None:
        current_body(self.bodies).robot.forget_obstacles()


class FleetLocker(Locker):
    """The one locker the executors see: codes are issued at the calling instruction's
    robot's locker, and every locker's events reach every subscriber."""

    def __init__(self, bodies: Sequence[Body]) -> None:
        super().__init__()
        self.bodies = list(bodies)
        self._issued_at: dict[str, Locker] = {}  # code id → the locker that issued it
        for body in self.bodies:
            body.locker.listen(self._publish)

    async def _start(self) -> None:
        for body in self.bodies:
            await body.locker.start()

    async def _stop(self) -> None:
        for body in reversed(self.bodies):
            await body.locker.stop()

    async def issue_code(
        self, *, instruction_id: str, person: str, purpose: Purpose, item: str
    ) -> QRCode:
        locker = current_body(self.bodies).locker
        code = await locker.issue_code(
            instruction_id=instruction_id, person=person, purpose=purpose, item=item
        )
        self._issued_at[code.code_id] = locker
        while len(self._issued_at) > SERVED_KEPT * 8:  # codes live minutes: keep the recent
            self._issued_at.pop(next(iter(self._issued_at)))
        return code

    async def status(self) -> LockStatus:
        return await current_body(self.bodies).locker.status()

    def issued_at(self, code_id: str) -> Locker | None:
        """The locker that issued ``code_id`` since the start (None: unknown here)."""
        return self._issued_at.get(code_id)

    async def revoke(self, code_id: str) -> None:
        locker = self._issued_at.pop(code_id, None)
        for target in [locker] if locker is not None else [b.locker for b in self.bodies]:
            await target.revoke(code_id)

    def _publish(self, event: LockEvent) -> None:
        super()._publish(event)
