"""The simulator's robot bases: a kinematic one, and an observer around any base.

``SimRobot`` drives at constant speed along ``distance(a, b)`` metres: the cheap default for
the evaluation. ``ObservedRobot`` wraps whichever base serves the assistant (``SimRobot``,
``NavigatorRobot`` with AMCL, later a real one) and tells the simulated office where the
robot stands, so the simulated people walk to it for hand-overs the same way whatever base
drives. The assistant only ever sees the ``RobotBase`` interface.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol, runtime_checkable

from assistantx.core.clock import Clock
from assistantx.core.errors import UnreachableError
from assistantx.core.office import Office
from assistantx.core.ports.robot import MoveResult, Pose, RobotBase, RobotState

DistanceFn = Callable[[str, str], float]


@runtime_checkable
class Relocatable(Protocol):
    """A base that can be put down at a place without driving (a restored simulation)."""

    def relocate(self, place: str) -> None: ...


class SimRobot(RobotBase):
    """A kinematic base: drives at constant speed along ``distance(a, b)`` metres. It has no
    floor map, so ``path_length`` is None (the caller's straight line is its own measure)."""

    def __init__(
        self, office: Office, clock: Clock, distance: DistanceFn, speed_mps: float
    ) -> None:
        super().__init__()
        self._office = office
        self._clock = clock
        self._distance = distance
        self._speed = speed_mps
        self.place: str | None = office.robot.home
        self.moving = False
        self.goal: str | None = None
        self.odometer_m = 0.0

    async def move_to(self, location_id: str) -> MoveResult:
        try:
            target = self._office.location(location_id)
        except KeyError as exc:
            raise UnreachableError(f"no anchor for location {location_id!r}") from exc
        start = self.place or self._office.robot.home
        distance = self._distance(start, target.id) if start != target.id else 0.0
        duration = distance / self._speed
        self.moving, self.place, self.goal = True, None, target.id
        try:
            await self._clock.sleep(duration)
        finally:
            # Cancelled mid-way, the kinematic base is simply taken to stand at the target.
            self.moving, self.place, self.goal = False, target.id, None
        self.odometer_m += distance
        return MoveResult(place=target.id, distance_m=distance, duration_s=duration)

    def relocate(self, place: str) -> None:
        self.place = place

    def state(self) -> RobotState:
        loc = self._office.location(self.place or self._office.robot.home)
        return RobotState(
            place=self.place,
            pose=Pose(x=loc.x, y=loc.y),
            moving=self.moving,
            goal=self.goal,
            odometer_m=self.odometer_m,
        )


class ObservedRobot(RobotBase):
    """Delegates to ``base``; keeps place, motion and distance for the simulated office and
    calls ``on_arrived`` after every arrival (people with a code for that place come)."""

    def __init__(
        self, base: RobotBase, home: str, on_arrived: Callable[[str], None] | None = None
    ) -> None:
        super().__init__()
        self.base = base
        self.place: str | None = base.state().place or home
        self.moving = False
        self.odometer_m = 0.0  # across restarts (restored), unlike a fresh base's own
        self._on_arrived = on_arrived

    async def _start(self) -> None:
        await self.base.start()

    async def _stop(self) -> None:
        await self.base.stop()

    async def move_to(self, location_id: str) -> MoveResult:
        self.moving, self.place = True, None
        try:
            result = await self.base.move_to(location_id)
        finally:
            self.moving = False
            self.place = self.base.state().place  # None when it failed between places
        self.odometer_m += result.distance_m
        if self._on_arrived is not None:
            self._on_arrived(result.place)
        return result

    def path_length(self, a: str, b: str) -> float | None:
        return self.base.path_length(a, b)

    def forget_obstacles(self) -> None:
        self.base.forget_obstacles()

    def state(self) -> RobotState:
        # Motion as the base reports it: a base still planning its path has not left its place.
        return self.base.state().model_copy(update={"odometer_m": self.odometer_m})

    def restore(self, place: str, odometer_m: float) -> None:
        """Where a journaled simulation left the robot; a base that cannot be put down there
        must have been built standing at ``place``."""
        if isinstance(self.base, Relocatable):
            self.base.relocate(place)
        self.place = place
        self.odometer_m = odometer_m
