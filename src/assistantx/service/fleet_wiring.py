"""Several robots for the service (``ASSISTANTX_ROBOTS`` > 1): the composition of
``sim.fleet`` with the service's clock, lock keys and navigator settings.

Robot 1 is the service's usual robot (standing where the journal left it, with the lock
``ASSISTANTX_LOCK_ID``); robots 2, 3 start at their parking places with in-process lockers
``<lock id>-2``, ``-3`` on the same keys (every code stays readable by the code book and the
ledger). They share the floor through ``nav.traffic``. Only on the default office map (its
parking places are known) and with in-process locks and navigator bases; anything else is
refused at start in one line.
"""

from __future__ import annotations

from assistantx.adapters.lock.protocol.keys import LockKeys
from assistantx.adapters.robot.navigator import DEFAULT_MAP, NavigatorRobot
from assistantx.core.clock import Clock
from assistantx.core.office import Office
from assistantx.core.ports.lock import Locker
from assistantx.core.settings import Settings
from assistantx.nav.traffic import Traffic
from assistantx.sim.fleet import PARKING, SimFleet, fleet_base, fleet_floor, join_fleet
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.local import LocalLocker
from assistantx.sim.office import SimOffice


class FleetSettingsError(ValueError):
    """Settings a fleet cannot run with."""


def check_fleet_settings(s: Settings) -> None:
    if s.robots <= 1:
        return
    if s.robots > len(PARKING):
        raise FleetSettingsError(f"ASSISTANTX_ROBOTS: at most {len(PARKING)} robots")
    if s.robot != "navigator":
        raise FleetSettingsError("ASSISTANTX_ROBOTS > 1 needs ASSISTANTX_ROBOT=navigator")
    if s.lock != "local":
        raise FleetSettingsError("ASSISTANTX_ROBOTS > 1 needs ASSISTANTX_LOCK=local")
    if s.map is not None and s.map.resolve() != DEFAULT_MAP.resolve():
        raise FleetSettingsError(
            "ASSISTANTX_ROBOTS > 1 runs on the default office map only (its parking places)"
        )


def first_robot(s: Settings, office: Office, clock: Clock, place: str | None) -> NavigatorRobot:
    """Robot 1, on the floor it will share with the others."""
    check_fleet_settings(s)
    floor = fleet_floor(DEFAULT_MAP, s.map_anchors)
    return fleet_base(
        office,
        clock,
        0,
        floor,
        Traffic(clock),
        localize=s.robot_localize,
        start=place or office.robot.home,
    )


def join_robots(
    s: Settings, sim: SimOffice, first: NavigatorRobot, keys: LockKeys, clock: Clock
) -> SimFleet:
    """Robots 2.. with their lockers, joined to ``sim`` and its robot 1."""
    assert first.traffic is not None
    floor = (first.grid, first.anchors)
    bases = [first] + [
        fleet_base(sim.office, clock, n, floor, first.traffic, localize=s.robot_localize)
        for n in range(1, s.robots)
    ]
    expiry_s = s.lock_code_expiry_min * 60
    lockers: list[Locker] = [sim.locker]
    for n in range(1, s.robots):
        controller = LockController(f"{s.lock_id}-{n + 1}", keys.codes, clock)
        lockers.append(LocalLocker(controller, clock=clock, expiry_s=expiry_s, render_png=False))
    return join_fleet(sim, bases, lockers, first.traffic)
