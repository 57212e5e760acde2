"""The robots' and the locker's state."""

from __future__ import annotations

from fastapi import APIRouter

from assistantx.core.ports.lock import LockStatus
from assistantx.core.ports.robot import RobotState
from assistantx.service.deps import Caller, Runtime
from assistantx.service.robots import NamedRobotState, robot_states

router = APIRouter(prefix="/v1", tags=["devices"])


@router.get("/robot", response_model=RobotState)
async def robot(runtime: Runtime, caller: Caller) -> RobotState:
    """Pose, place (None while driving), goal, planned path; plus the instruction holding the
    robot (``holder``). With several robots: robot 1 (``/v1/robots`` lists them all)."""
    return runtime.sim.robot.state().model_copy(update={"holder": runtime.assistant.lease.holder})


@router.get("/robots", response_model=list[NamedRobotState])
async def robots(runtime: Runtime, caller: Caller) -> list[NamedRobotState]:
    """Every robot of the office, in order, each as ``/v1/robot`` shows one, with its name."""
    return robot_states(runtime)


@router.get("/locker", response_model=LockStatus)
async def locker(runtime: Runtime, caller: Caller) -> LockStatus:
    return await runtime.locker.status()
