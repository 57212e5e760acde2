"""Shared fixtures, and the guard that fails any test reaching beyond 127.0.0.1."""

from __future__ import annotations

import socket

import pytest

from fakes.fixtures import scripted_llm  # noqa: F401  (the scripted model server, for every folder)
from netguard import guarded_connect, guarded_connect_ex, guarded_getaddrinfo


@pytest.fixture(autouse=True)
def _no_network(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(socket.socket, "connect", guarded_connect)
    monkeypatch.setattr(socket.socket, "connect_ex", guarded_connect_ex)
    monkeypatch.setattr(socket, "getaddrinfo", guarded_getaddrinfo)
