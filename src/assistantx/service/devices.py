"""The robot's and the locker's state."""

from __future__ import annotations

from fastapi import APIRouter

from assistantx.core.ports.lock import LockStatus
from assistantx.core.ports.robot import RobotState
from assistantx.service.deps import Caller, Runtime

router = APIRouter(prefix="/v1", tags=["devices"])


@router.get("/robot", response_model=RobotState)
async def robot(runtime: Runtime, caller: Caller) -> RobotState:
    """Pose, place (None while driving), goal, planned path; plus the instruction holding the
    robot (``holder``)."""
    return runtime.sim.robot.state().model_copy(update={"holder": runtime.assistant.lease.holder})


@router.get("/locker", response_model=LockStatus)
async def locker(runtime: Runtime, caller: Caller) -> LockStatus:
    return await runtime.locker.status()
