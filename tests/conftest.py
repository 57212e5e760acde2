"""Shared fixtures, and the guard that fails any test reaching beyond 127.0.0.1."""

from __future__ import annotations

import gc
import os
import socket
import sys
from collections.abc import Generator, Iterator
from pathlib import Path

import pytest

from fakes.fixtures import scripted_llm  # noqa: F401  (the scripted model server, for every folder)
from helpers.children import descendants
from helpers.dataset_offices import harbour  # noqa: F401  (the dataset's harbour office, parsed once)
from helpers.markers import never_selects
from helpers.postgres import (  # noqa: F401  (the tests' PostgreSQL, and both store backends)
    backend,
    database_url,
    postgres_cluster,
    postgres_url,
)
from helpers.xdist_schedule import ModuleScheduling, long_modules_first, name_groups_in_ids
from netguard import guarded_connect, guarded_connect_ex, guarded_getaddrinfo

# Under pytest-xdist (`make test` runs two workers, `--dist loadgroup`), the tests that share
# one session-wide server stay on one worker, so it starts once, not once per worker: Synapse
# and the gateway port written into its appservice registration, and the llama.cpp server.
_ONE_WORKER_EACH = ("synapse", "llm_server")


# The folders whose every test needs one server from outside, and that server's marker.
# Every test in the folder carries the marker (added below, whatever its module says), so a
# run whose `-m` deselects the marker (`make test-fast`) does not import the folder at all:
# matrix-nio and Playwright cost about 1.3 CPU-s of collection in each xdist worker.
_TESTS = Path(__file__).parent
_FOLDER_MARKERS = {"synapse": "synapse", "browser": "browser", "llm_server": "llm_server"}


def pytest_ignore_collect(collection_path: Path, config: pytest.Config) -> bool | None:
    marker = _FOLDER_MARKERS.get(collection_path.name)
    if marker is None or collection_path.parent != _TESTS:
        return None
    return True if never_selects(config.getoption("markexpr"), marker) else None


# A wrapper: the markers go on before any other hook (`-m` deselects by them); after every other
# hook (xdist's own included), each group goes into its tests' ids and the modules with a long
# test go first (see `helpers.xdist_schedule`).
@pytest.hookimpl(wrapper=True, tryfirst=True)
def pytest_collection_modifyitems(
    config: pytest.Config, items: list[pytest.Item]
) -> Generator[None, None, None]:
    for item in items:
        folder = item.path.relative_to(_TESTS).parts[0] if item.path.is_relative_to(_TESTS) else ""
        if folder in _FOLDER_MARKERS:
            item.add_marker(_FOLDER_MARKERS[folder])
    if not config.pluginmanager.hasplugin("xdist"):
        return (yield)
    for item in items:
        for marker in _ONE_WORKER_EACH:
            if item.get_closest_marker(marker) is not None:
                item.add_marker(pytest.mark.xdist_group(marker))
        # Tests that share what one of them builds once per process (a cache, a module's
        # fixture) are one group too: split over two workers, each worker would build it.
        shared = item.get_closest_marker("shares_worker")
        if shared is not None:
            item.add_marker(pytest.mark.xdist_group(shared.args[0]))
        elif item.get_closest_marker("browser") is not None:
            # each browser module launches its own Playwright and Chromium (a module fixture)
            item.add_marker(pytest.mark.xdist_group(f"browser-{item.path.stem}"))
    result = yield
    if getattr(config.option, "loadgroup", False):  # set in an xdist worker of `--dist loadgroup`
        name_groups_in_ids(items)
        items[:] = long_modules_first(items)
    return result


# `--dist loadgroup` hands out whole modules (and groups), not single tests: see
# `helpers.xdist_schedule.ModuleScheduling`.
@pytest.hookimpl(optionalhook=True)
def pytest_xdist_make_scheduler(config: pytest.Config, log: object) -> ModuleScheduling | None:
    return ModuleScheduling(config, log) if config.getvalue("dist") == "loadgroup" else None


# What collection built (every test module, its imports, the items and their parameters)
# lives as long as the process: frozen (``gc.freeze``, as ``assistantx serve`` freezes its
# start-up), so the full collections the tests' garbage sets off walk only what came since,
# not the whole heap again (about 24 full collections a worker in `make test-fast`). Objects
# frozen are still freed by reference counting; only cycles among them are no longer
# collected, and collection makes none that matter.
@pytest.hookimpl(trylast=True)
def pytest_collection_finish(session: pytest.Session) -> None:
    gc.freeze()


# Every httpx client builds an SSL context; from one bundle file (SSL_CERT_FILE, or certifi's)
# that parses some 150 PEM certificates, 40-60 ms of CPU per client, and the suite makes
# thousands (each in-process service, model adapter and test client). The same system store
# as its hashed folder loads a certificate only when a handshake needs it, which no test does
# (the guard below keeps them on 127.0.0.1, in plain HTTP). Subprocesses inherit the same trust.
_SYSTEM_CERTS = Path("/etc/ssl/certs")


def pytest_configure(config: pytest.Config) -> None:
    bundle = str(_SYSTEM_CERTS / "ca-certificates.crt")
    own_file = os.environ.get("SSL_CERT_FILE", bundle) != bundle
    own_dir = os.environ.get("SSL_CERT_DIR", str(_SYSTEM_CERTS)) != str(_SYSTEM_CERTS)
    if own_file or own_dir or not any(_SYSTEM_CERTS.glob("*.0")):
        return  # a trust store of the user's own, or no hashed system store: left as it is
    os.environ.pop("SSL_CERT_FILE", None)
    os.environ["SSL_CERT_DIR"] = str(_SYSTEM_CERTS)


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
