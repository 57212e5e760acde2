"""Fixtures of the lock tests: shared keys, a simulated clock, a controller."""

from __future__ import annotations

import pytest

from assistantx.clock import SimClock
from assistantx.lock import CodeIssuer, LockController, LockKeys

LOCK_ID = "locker-1"


@pytest.fixture
def keys() -> LockKeys:
    return LockKeys.from_secret("test secret shared by lock and assistant")


@pytest.fixture
def clock() -> SimClock:
    return SimClock(start=1_000.0)


@pytest.fixture
def controller(keys: LockKeys, clock: SimClock) -> LockController:
    return LockController(LOCK_ID, keys.codes, clock)


@pytest.fixture
def issuer(keys: LockKeys, clock: SimClock) -> CodeIssuer:
    return CodeIssuer(LOCK_ID, keys.codes, clock, expiry_s=600, render=False)
