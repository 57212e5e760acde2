"""Shared fixtures, and the guard that fails any test reaching beyond 127.0.0.1."""

from __future__ import annotations

import os
import socket
import sys
from collections.abc import Iterator

import pytest

from fakes.fixtures import scripted_llm  # noqa: F401  (the scripted model server, for every folder)
from helpers.children import descendants
from helpers.postgres import (  # noqa: F401  (the tests' PostgreSQL, and both store backends)
    backend,
    database_url,
    postgres_cluster,
    postgres_url,
)
from netguard import guarded_connect, guarded_connect_ex, guarded_getaddrinfo


# Under pytest-xdist (`make test` runs two workers, `--dist loadgroup`), the tests that share
# one session-wide server stay on one worker, so it starts once, not once per worker: Synapse
# and the gateway port written into its appservice registration, and the llama.cpp server.
_ONE_WORKER_EACH = ("synapse", "llm_server")


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    if not config.pluginmanager.hasplugin("xdist"):
        return
    for item in items:
        for marker in _ONE_WORKER_EACH:
            if item.get_closest_marker(marker) is not None:
                item.add_marker(pytest.mark.xdist_group(marker))


@pytest.fixture(autouse=True)
def _no_network(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(socket.socket, "connect", guarded_connect)
    monkeypatch.setattr(socket.socket, "connect_ex", guarded_connect_ex)
    monkeypatch.setattr(socket, "getaddrinfo", guarded_getaddrinfo)


# multiprocessing's resource tracker lives as long as its parent by design (it cleans up what
# a killed worker left); it ends when the test process does.
_LIVES_WITH_THE_PROCESS = ("multiprocessing.resource_tracker",)


@pytest.fixture(scope="session", autouse=True)
def _no_process_left() -> Iterator[None]:
    """Fails the run if a test left a process running: a server, worker or tool it started
    and did not stop (a leak that a kill of the test run would orphan)."""
    yield
    # The planner's worker is process-wide (one per process, started on first use); the
    # interpreter's exit would close it, so close it here before looking.
    plan_process = sys.modules.get("assistantx.nav.plan_process")
    if plan_process is not None:
        plan_process.PLAN_PROCESS.close()
    left = [
        child
        for child in descendants(os.getpid())
        if not any(name in child.command for name in _LIVES_WITH_THE_PROCESS)
    ]
    if left:
        pytest.fail(
            "processes left running after the tests: "
            + "; ".join(f"{c.pid}: {c.command[:120]}" for c in left),
            pytrace=False,
        )
