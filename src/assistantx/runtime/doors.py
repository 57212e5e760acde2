"""A closed door on the way: say so in words, then come back and try again until it opens.

A door is the one blockage people fix in minutes (someone opens it, a meeting ends), so a move
that fails with DoorClosedError does not fail the step at once: the requester is told, once,
which door and what happens next ("I'll come back when it's open"), and the robot tries the
drive again every ``retry_s`` until ``patience_s`` has passed. Only then does the error reach
the loop, whose failure summary asks the requester to send the request again. Any other
error of the drive goes straight through, as before (a plain BlockedError too, except on
a try after a closed door: the robot remembers the door it saw, so its plan fails at once).
"""

from __future__ import annotations

import logging
from collections.abc import Awaitable, Callable
from dataclasses import dataclass

from assistantx.core.clock import Clock
from assistantx.core.errors import BlockedError, DoorClosedError
from assistantx.core.ports.robot import MoveResult, RobotBase

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class DoorPatience:
    retry_s: float = 180.0  # office clock: how often the robot goes back to the door
    patience_s: float = 900.0  # after this long the move fails as before


def closed_door_note(place_name: str, patience: DoorPatience) -> str:
    every = round(patience.retry_s / 60)
    up_to = round(patience.patience_s / 60)
    return (
        f"The door on the way to {place_name} is closed. I'll come back when it's open: I "
        f"try again every {every} minute{'s' if every != 1 else ''}, for up to {up_to} minutes."
    )


async def drive_past_closed_doors(
    robot: RobotBase,
    place: str,
    clock: Clock,
    tell: Callable[[str], Awaitable[None]],
    place_name: str,
    patience: DoorPatience = DoorPatience(),
) -> MoveResult:
    """``robot.move_to(place)``, waiting out a closed door (``tell``: a note to the
    requester, sent once)."""
    deadline = clock.timer() + patience.patience_s
    told = False
    while True:
        try:
            return await robot.move_to(place)
        except BlockedError as exc:
            # Once a door was the reason, a way still blocked on a later try is that door
            # still shut (the robot remembers it: its plan fails before it sets off).
            if not (told or isinstance(exc, DoorClosedError)):
                raise
            if clock.timer() + patience.retry_s > deadline:
                raise
            if not told:
                await tell(closed_door_note(place_name, patience))
                told = True
            logger.info("a door to %s is closed: trying again in %.0f s", place, patience.retry_s)
            await clock.sleep(patience.retry_s)
            robot.forget_obstacles()  # it comes back to look: the door may be open now
