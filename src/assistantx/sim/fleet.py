"""A simulated office served by several robots: each a navigator on the office map with its
own in-process locker, sharing the floor through ``nav.traffic``, leased per robot
(``runtime.fleet``).

``sim_fleet`` builds it on a ``SimOffice``: the office's first robot is robot 1, the others
are added to the simulated office (people walk to the robot that serves their instruction),
and the assistant gets a ``FleetRobot``, a ``FleetLocker`` and the ``FleetLease``.

Parking places: a robot nobody needs waits where it is in nobody's way. They are points of
the map beside no desk (``PARKING``: map corners and ends of the office floor), added as
extra anchors named ``parking 1``, ``parking 2``... so robots can be sent there; they are no
office location, so an instruction never names one. The robots start there.
"""

from __future__ import annotations

import hashlib
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from assistantx.adapters.lock.protocol.keys import Keyring
from assistantx.adapters.robot.navigator import DEFAULT_MAP, NavigatorRobot
from assistantx.agents.base import ReasonerFactory
from assistantx.core.clock import Clock
from assistantx.core.office import Office
from assistantx.core.ports.lock import Locker
from assistantx.memory.short_term import ShortTermMemory
from assistantx.nav.anchors import Anchor, load_anchors
from assistantx.nav.occupancy_map import OccupancyMap, load_map
from assistantx.nav.traffic import Traffic
from assistantx.runtime.assistant import Assistant, AssistantParts
from assistantx.runtime.fleet import Body, FleetLease, FleetLocker, FleetRobot
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.local import LocalLocker
from assistantx.sim.office import SimOffice
from assistantx.sim.requester import Wish

# On the default office map: free corners and ends of the floor, away from every desk stop.
PARKING: tuple[tuple[float, float], ...] = ((1.2, 1.2), (1.2, 10.5), (39.0, 1.5))


@dataclass
class SimFleet:
    sim: SimOffice
    lease: FleetLease
    robot: FleetRobot
    locker: FleetLocker
    traffic: Traffic
    bodies: list[Body]
    wishes: dict[str, Wish] = field(default_factory=dict)  # instruction id → what is wanted

    def assistant(
        self, reasoner_factory: ReasonerFactory, *, limits: LoopLimits | None = None
    ) -> Assistant:
        """The Assistant on this fleet: the simulated people learn of every instruction (and
        of what its requester wants, from ``wishes``) and forget it when it ends."""
        sim = self.sim
        assistant = Assistant(
            AssistantParts(
                office=sim.office,
                messenger=sim.messenger,
                robot=self.robot,
                locker=self.locker,
                clock=sim.clock,
                reasoner_factory=reasoner_factory,
                limits=limits or LoopLimits(),
                fleet=self.lease,
            )
        )

        async def register(stm: ShortTermMemory) -> None:
            wish = self.wishes.get(stm.instruction_id)
            sim.register_instruction(stm.instruction_id, stm.requester, wish, text=stm.text)

        async def forget(stm: ShortTermMemory) -> None:
            sim.end_instruction(stm.instruction_id)

        assistant.on_instruction_start(register)
        assistant.on_instruction_end(forget)
        return assistant

    async def __aenter__(self) -> SimFleet:
        await self.robot.start()
        await self.locker.start()
        return self

    async def __aexit__(self, *exc: object) -> None:
        await self.lease.stop()
        await self.locker.stop()
        await self.robot.stop()


def parking_name(n: int) -> str:
    return f"parking {n + 1}"


def fleet_floor(
    map_yaml: Path = DEFAULT_MAP,
    anchors_yaml: Path | None = None,
    parking: Sequence[tuple[float, float]] = PARKING,
) -> tuple[OccupancyMap, dict[str, Anchor]]:
    """The map and its anchors, with the parking places added as anchors."""
    grid = load_map(map_yaml)
    anchors: dict[str, Anchor] = dict(
        load_anchors(anchors_yaml or map_yaml.with_name(map_yaml.stem + ".anchors.yaml"))
    )
    for n, (x, y) in enumerate(parking):
        anchors[parking_name(n)] = Anchor(x=x, y=y, yaw=0.0)
    return grid, anchors


def fleet_base(
    office: Office,
    clock: Clock,
    n: int,
    floor: tuple[OccupancyMap, dict[str, Anchor]],
    traffic: Traffic,
    *,
    localize: bool = False,
    start: str | None = None,
) -> NavigatorRobot:
    """Robot ``n + 1``'s base, standing at ``start`` (default: its parking place)."""
    grid, anchors = floor
    return NavigatorRobot(
        office,
        grid,
        anchors,
        clock,
        seed=n,
        localize=localize,
        start=start or parking_name(n),
        traffic=traffic,
        name=robot_name(n),
    )


def robot_name(n: int) -> str:
    return f"robot {n + 1}"


def join_fleet(
    sim: SimOffice,
    bases: Sequence[NavigatorRobot],
    lockers: Sequence[Locker],
    traffic: Traffic,
) -> SimFleet:
    """``sim``'s robot (``bases[0]``, with ``lockers[0]``) and the others as one fleet."""
    bodies = [Body(robot_name(0), sim.robot, lockers[0], parking=parking_name(0))]
    for n in range(1, len(bases)):
        observed = sim.add_robot(robot_name(n), bases[n], lockers[n], parking_name(n))
        bodies.append(Body(robot_name(n), observed, lockers[n], parking=parking_name(n)))
    lease = FleetLease(bodies, speed_mps=sim.office.robot.speed_mps)

    def robot_of(instruction_id: str) -> str | None:
        body = lease.body_of(instruction_id)
        return None if body is None else body.name

    sim.robot_of = robot_of
    return SimFleet(
        sim,
        lease,
        FleetRobot(bodies, [loc.id for loc in sim.office.locations]),
        FleetLocker(bodies),
        traffic,
        bodies,
    )


def sim_fleet(
    office: Office,
    clock: Clock,
    size: int,
    *,
    map_yaml: Path = DEFAULT_MAP,
    anchors_yaml: Path | None = None,
    parking: Sequence[tuple[float, float]] = PARKING,
    reply_delay_s: float = 20.0,
    handover_delay_s: float = 30.0,
) -> SimFleet:
    """``size`` robots (at most one per parking place) in a new simulated office, all
    simulated: kinematic driving along planned paths, in-process lockers."""
    if not 1 <= size <= len(parking):
        raise ValueError(f"a fleet of 1 to {len(parking)} robots, not {size}")
    floor = fleet_floor(map_yaml, anchors_yaml, parking)
    traffic = Traffic(clock)
    bases = [fleet_base(office, clock, n, floor, traffic) for n in range(size)]
    lockers = [sim_locker(n, clock) for n in range(size)]
    sim = SimOffice(
        office,
        clock=clock,
        robot=bases[0],
        locker=lockers[0],
        reply_delay_s=reply_delay_s,
        handover_delay_s=handover_delay_s,
    )
    return join_fleet(sim, bases, lockers, traffic)


def sim_locker(n: int, clock: Clock) -> LocalLocker:
    key = hashlib.sha256(f"assistantx-sim-fleet-{n}".encode()).digest()
    controller = LockController(f"sim-locker-{n + 1}", Keyring.single("sim", key), clock)
    return LocalLocker(controller, clock=clock, render_png=False)
