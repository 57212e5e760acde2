"""The dataset's own office files, for the tests that run on them, and the ``harbour``
fixture (tests/conftest.py offers it everywhere): the harbour office parsed once, since an
office is immutable."""

from __future__ import annotations

import functools
from pathlib import Path

import pytest

from assistantx.core.office import Office, load_office

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_FILE = ROOT / "dataset" / "office.yaml"
HARBOUR_FILE = ROOT / "dataset" / "offices" / "harbour" / "office.yaml"


@functools.cache
def default_office() -> Office:
    return load_office(DEFAULT_FILE)


@functools.cache
def harbour_office() -> Office:
    return load_office(HARBOUR_FILE)


@pytest.fixture(scope="session")
def harbour() -> Office:
    """The dataset's harbour office (dataset/offices/harbour)."""
    return harbour_office()
