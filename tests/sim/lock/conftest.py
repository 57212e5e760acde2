"""The lock emulator's tests use the lock fixtures shared with the protocol's tests."""

from helpers.lock import (  # noqa: F401 (fixtures)
    clock_fixture,
    controller_fixture,
    issuer_fixture,
    keys_fixture,
)
