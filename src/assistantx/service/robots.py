"""Every robot of the office as the service shows it: the ``/v1/robots`` rows and the
per-robot gauges of ``/metrics`` (``assistantx_robot_*{robot="robot 2"}``).

One robot shows as ``robot 1``; with ``ASSISTANTX_ROBOTS`` > 1 each robot of the fleet, with
the instruction it serves (``holder``) and how many it was given since the start.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING

from prometheus_client.metrics_core import GaugeMetricFamily, Metric
from pydantic import Field

from assistantx.core.ports.robot import RobotState
from assistantx.sim.office import HandOverDesk

if TYPE_CHECKING:
    from assistantx.service.runtime import ServiceRuntime


class NamedRobotState(RobotState):
    name: str = Field(description="the robot as people call it: 'robot 1', 'robot 2'")
    served: int = Field(default=0, description="instructions it was given since the start")


def robot_states(runtime: ServiceRuntime) -> list[NamedRobotState]:
    fleet = runtime.fleet
    if fleet is None:
        state = runtime.sim.robot.state().model_dump(exclude={"holder"})
        holder = runtime.assistant.lease.holder
        return [NamedRobotState(**state, holder=holder, name="robot 1")]
    return [
        NamedRobotState(
            **body.robot.state().model_dump(exclude={"holder"}),
            holder=fleet.lease.holder_of(body),
            name=body.name,
            served=body.served,
        )
        for body in fleet.bodies
    ]


async def desk_for_code(runtime: ServiceRuntime, code_id: str) -> HandOverDesk:
    """Where a person holds up ``code_id``: the locker of the robot that issued it (robot 1's
    when one robot, or when the code was issued before this start)."""
    if runtime.fleet is not None:
        locker = runtime.fleet.locker.issued_at(code_id)
        if isinstance(locker, HandOverDesk):
            return locker
    return runtime.sim.desk


async def open_desk(runtime: ServiceRuntime) -> HandOverDesk | None:
    """A locker whose door stands open (robot 1's first), None when every door is shut."""
    if runtime.fleet is None:
        return runtime.sim.desk if (await runtime.locker.status()).door == "open" else None
    for body in runtime.fleet.bodies:
        if (await body.locker.status()).door == "open" and isinstance(body.locker, HandOverDesk):
            return body.locker
    return None


class RobotGauges:
    """Gauges per robot, read at scrape time."""

    def __init__(self, states: Callable[[], list[NamedRobotState]]) -> None:
        self._states = states

    def describe(self) -> Iterable[Metric]:
        return self._families()

    def collect(self) -> Iterable[Metric]:
        busy, driving, odometer, served = families = self._families()
        for robot in self._states():
            busy.add_metric([robot.name], 1.0 if robot.holder else 0.0)
            driving.add_metric([robot.name], 1.0 if robot.moving else 0.0)
            odometer.add_metric([robot.name], robot.odometer_m)
            served.add_metric([robot.name], float(robot.served))
        return families

    @staticmethod
    def _families() -> list[GaugeMetricFamily]:
        labels = ["robot"]
        return [
            GaugeMetricFamily(
                "assistantx_robot_busy", "1 while an instruction holds the robot", labels=labels
            ),
            GaugeMetricFamily(
                "assistantx_robot_driving", "1 while the robot drives", labels=labels
            ),
            GaugeMetricFamily(
                "assistantx_robot_odometer_meters", "distance the robot has driven", labels=labels
            ),
            GaugeMetricFamily(
                "assistantx_robot_instructions_served",
                "instructions the robot was given since the start",
                labels=labels,
            ),
        ]
