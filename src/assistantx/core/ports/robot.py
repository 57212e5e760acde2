"""The robot base interface: drive to a named place of the office.

A concrete base (the in-process navigator, the simulator's kinematic base, later a ROS 2
bridge) resolves a location id to its map anchor, plans, drives and reports arrival, or
raises a RobotError subclass (UnreachableError, BlockedError, LocalizationLostError).
"""

from __future__ import annotations

from abc import ABC, abstractmethod

from pydantic import BaseModel, Field

from assistantx.core.lifecycle import Component


class Pose(BaseModel):
    x: float = Field(description="metres, map frame")
    y: float = Field(description="metres, map frame")
    yaw: float = Field(default=0.0, description="radians, counter-clockwise from +x")


class MoveResult(BaseModel):
    place: str = Field(description="the location id the robot arrived at")
    distance_m: float
    duration_s: float


class RobotState(BaseModel):
    place: str | None = Field(description="location id the robot stands at, None while driving")
    pose: Pose
    moving: bool = False
    goal: str | None = Field(default=None, description="location id the robot drives to")
    holder: str | None = Field(
        default=None, description="the instruction holding the robot (set by the service)"
    )
    path: list[tuple[float, float]] = Field(default_factory=list, description="planned path, m")
    particles: list[tuple[float, float, float]] | None = Field(
        default=None, description="a sample of the localizer's particle cloud (x, y, yaw)"
    )
    odometer_m: float = Field(default=0.0, description="distance driven since start")


class RobotBase(Component, ABC):
    """A mobile base that drives to the office's named locations; started and stopped as a
    ``Component`` (initialise in ``_start``, release in ``_stop``)."""

    @abstractmethod
    async def move_to(self, location_id: str) -> MoveResult:
        """Drive to the anchor of ``location_id``; raise RobotError on failure."""

    @abstractmethod
    def state(self) -> RobotState:
        """The current pose, place, path and (if localizing) particle sample."""

    def forget_obstacles(self) -> None:
        """Forget the obstacles the base has seen that its map lacks (nav2's "clear the
        costmap"), to look again on the next move: a door may have been opened meanwhile.
        A base without a memory of obstacles has nothing to forget."""

    def path_length(self, a: str, b: str) -> float | None:
        """Metres along the path a person would take from location ``a`` to ``b`` on this
        base's floor map; None when the base has no map (callers then measure straight
        lines). Raises UnreachableError when the map has no path. May take seconds on a big
        floor: call it off the event loop."""
        del a, b
        return None
