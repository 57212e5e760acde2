"""SIGTERM stops the service within a couple of seconds, even with live event streams open."""

from __future__ import annotations

import signal
import threading
import time
from pathlib import Path

import httpx
import pytest

from helpers.children import descendants, still_running
from helpers.eventually import eventually_sync
from service.server import OPERATOR, free_port, serve

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow


def _follow(url: str, lines: list[str], opened: threading.Event) -> None:
    headers = {"Authorization": f"Bearer {OPERATOR}"}
    with (
        httpx.Client(base_url=url, timeout=30) as client,
        client.stream("GET", "/v1/events", headers=headers) as response,
    ):
        opened.set()
        for line in response.iter_lines():
            lines.append(line)


def _open_streams(url: str) -> int:
    headers = {"Authorization": f"Bearer {OPERATOR}"}
    text = httpx.get(f"{url}/metrics", headers=headers, timeout=10).text
    [line] = [x for x in text.splitlines() if x.startswith("assistantx_event_streams ")]
    return int(float(line.split()[1]))


def test_sigterm_with_open_sse_streams_stops_quickly(tmp_path: Path) -> None:
    server = serve(tmp_path / "data", free_port())
    lines: list[str] = []
    followers = []
    try:
        for _ in range(2):
            opened = threading.Event()
            follower = threading.Thread(target=_follow, args=(server.url, lines, opened))
            follower.start()
            assert opened.wait(10)
            followers.append(follower)
        # Both streams subscribed to the live events (then a shutdown must end them).
        eventually_sync(
            lambda: _open_streams(server.url) == 2, what="two open event streams", timeout_s=10
        )
        started = time.monotonic()
        server.process.terminate()
        code = server.process.wait(10)
        took = time.monotonic() - started
    finally:
        server.stop()
    for follower in followers:
        follower.join(5)
        assert not follower.is_alive()  # the server ended the streams
    assert code in (0, -15)  # uvicorn re-raises the signal it handled once it has stopped
    assert took < 2.5, f"stopping took {took:.1f} s"
    log = server.log.read_text()
    assert "Application shutdown complete" in log  # the lifespan ran: journal closed
    assert "timeout graceful shutdown exceeded" not in log  # ended, not cancelled


def test_sigint_stops_the_service_and_its_planning_worker(tmp_path: Path) -> None:
    server = serve(tmp_path / "data", free_port())  # navigator with AMCL: plans in a worker
    try:
        children = [c.pid for c in descendants(server.process.pid)]
        assert any("spawn_main" in c.command for c in descendants(server.process.pid))
        server.process.send_signal(signal.SIGINT)
        code = server.process.wait(10)
    finally:
        server.stop()
    assert code in (0, 130, -2)  # uvicorn re-raises the SIGINT it handled; the CLI says 130
    # The worker is stopped with the robot; the resource tracker ends once its pipe closes.
    eventually_sync(
        lambda: still_running(children) == [], what="its processes to end", timeout_s=10
    )


def test_a_killed_service_leaves_no_planning_worker(tmp_path: Path) -> None:
    server = serve(tmp_path / "data", free_port())
    children = [c.pid for c in descendants(server.process.pid)]
    assert children  # the planning worker (and multiprocessing's resource tracker)
    server.kill()  # SIGKILL: no shutdown runs in the server
    # The worker notices its parent is gone and exits; the tracker follows once no process
    # holds its pipe.
    eventually_sync(lambda: still_running(children) == [], what="the orphans to exit", timeout_s=30)
