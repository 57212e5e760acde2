"""Fixtures for the symbolic reasoner's tests."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office, load_office


@pytest.fixture(scope="session")
def office() -> Office:
    return load_office()
