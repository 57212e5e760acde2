"""Fixtures shared by the lock protocol's tests (``tests/adapters/lock``) and the lock
emulator's (``tests/sim/lock``): one key set, a simulated clock, the emulator's controller and
a code issuer for it. Each conftest imports them from here (``*_fixture``: the
functions, named so that a test's parameter does not shadow them)."""

from __future__ import annotations

import pytest

from assistantx.adapters.lock.protocol import CodeIssuer, LockKeys
from assistantx.core.clock import SimClock
from assistantx.sim.lock.controller import LockController

LOCK_ID = "locker-1"


@pytest.fixture(name="keys")
def keys_fixture() -> LockKeys:
    return LockKeys.from_secret("test secret shared by lock and assistant")


@pytest.fixture(name="clock")
def clock_fixture() -> SimClock:
    return SimClock(start=1_000.0)


@pytest.fixture(name="controller")
def controller_fixture(keys: LockKeys, clock: SimClock) -> LockController:
    return LockController(LOCK_ID, keys.codes, clock)


@pytest.fixture(name="issuer")
def issuer_fixture(keys: LockKeys, clock: SimClock) -> CodeIssuer:
    return CodeIssuer(LOCK_ID, keys.codes, clock, expiry_s=600, render=False)
