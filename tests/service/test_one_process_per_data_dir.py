"""A second ``assistantx serve`` on a data folder in use, or on a taken port, exits with a
one-line error before it resumes anything: no duplicate steps, nothing journaled."""

from __future__ import annotations

import socket
import subprocess
import sys
from collections import Counter
from pathlib import Path

import httpx
import pytest

from assistantx.store.journal import Journal
from helpers.eventually import eventually_sync
from helpers.instructions import submit_stapler
from service.server import LEE, base_env, free_port, serve

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow

AUTH_LEE = {"Authorization": f"Bearer {LEE}"}
SLOW = {"ASSISTANTX_SPEEDUP": "1", "ASSISTANTX_SIM_UNAVAILABLE": "wang"}  # runs for minutes


def _serve_again(data_dir: Path, port: int) -> subprocess.CompletedProcess[str]:
    cmd = [sys.executable, "-m", "assistantx", "serve", "--host", "127.0.0.1", "--port", str(port)]
    return subprocess.run(
        cmd, env=base_env(data_dir, **SLOW), capture_output=True, text=True, timeout=60
    )


def _start_running(client: httpx.Client) -> str:
    iid = submit_stapler(client, AUTH_LEE)
    body = eventually_sync(
        lambda: client.get(f"/v1/instructions/{iid}", headers=AUTH_LEE).json(),
        until=lambda b: b["trace"] and b["trace"]["steps"],  # no trace while queued
        what="the instruction to start",
    )
    assert body["status"] == "running"
    return iid


def _events(data_dir: Path) -> list[tuple[str, str, int | None]]:
    journal = Journal.open(data_dir / "journal.sqlite3")
    try:
        return [(r.event.instruction_id, r.event.kind, r.event.step) for r in journal.events()]
    finally:
        journal.close()


def test_a_second_server_on_a_data_folder_in_use_exits_and_changes_nothing(
    tmp_path: Path,
) -> None:
    data_dir = tmp_path / "data"
    first = serve(data_dir, free_port(), **SLOW)
    try:
        with httpx.Client(base_url=first.url, timeout=10) as client:
            iid = _start_running(client)
            second = _serve_again(data_dir, free_port())
            assert second.returncode == 1
            assert second.stdout == ""
            [line] = second.stderr.strip().splitlines()
            assert "another assistantx process is serving from the data folder" in line
            assert str(data_dir) in line
            body = client.get(f"/v1/instructions/{iid}", headers=AUTH_LEE).json()
            assert body["status"] == "running"
    finally:
        first.kill()
    started = Counter(
        e for e in _events(data_dir) if e[1] in ("step_started", "instruction_started")
    )
    assert started and max(started.values()) == 1, started  # nobody resumed it a second time


def test_a_server_whose_port_is_taken_exits_before_resuming(tmp_path: Path) -> None:
    data_dir = tmp_path / "data"
    first = serve(data_dir, free_port(), **SLOW)
    try:
        with httpx.Client(base_url=first.url, timeout=10) as client:
            _start_running(client)
    finally:
        first.kill()  # the instruction stays running in the journal, the lock is free
    before = _events(data_dir)
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen(1)
        port = taken.getsockname()[1]
        second = _serve_again(data_dir, port)
    assert second.returncode == 1
    [line] = second.stderr.strip().splitlines()
    assert line.startswith(f"assistantx serve: cannot listen on 127.0.0.1:{port}")
    assert _events(data_dir) == before  # nothing resumed, nothing journaled
