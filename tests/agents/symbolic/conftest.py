"""Fixtures for the symbolic reasoner's tests."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, load_office
from helpers.clinic import clinic


@pytest.fixture(scope="session")
def office() -> Office:
    return load_office()


@pytest.fixture(scope="session")
def clinic_parser() -> InstructionParser:
    """The reader on the clinic (tests/helpers/clinic.py), one for all its tests."""
    return InstructionParser(clinic())
