"""The service on its real devices: the navigator base (planned path, AMCL particles, a pose
that moves while it drives) and the TCP locker behind ``assistantx lock-sim``."""

from __future__ import annotations

import subprocess
import sys
import threading
import time
from pathlib import Path

import httpx
import pytest

from service.server import LEE, OPERATOR, base_env, free_port, serve, sse

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow

AUTH_LEE = {"Authorization": f"Bearer {LEE}"}
AUTH_OP = {"Authorization": f"Bearer {OPERATOR}"}
SHARED_KEY = "the lock's shared secret for the service tests"


def _submit(client: httpx.Client, text: str = "Please bring me a stapler.") -> str:
    r = client.post("/v1/instructions", json={"requester": "lee", "text": text}, headers=AUTH_LEE)
    assert r.status_code == 202, r.text
    return str(r.json()["id"])


def _watch_robot(url: str, stop: threading.Event, seen: list[dict[str, object]]) -> None:
    with httpx.Client(base_url=url, headers=AUTH_OP, timeout=10) as client:
        while not stop.is_set():
            seen.append(client.get("/v1/robot").json())
            time.sleep(0.02)


def test_navigator_robot_reports_its_drive(tmp_path: Path) -> None:
    server = serve(tmp_path / "data", free_port())  # ASSISTANTX_ROBOT defaults to navigator
    seen: list[dict[str, object]] = []
    stop = threading.Event()
    watcher = threading.Thread(target=_watch_robot, args=(server.url, stop, seen))
    try:
        with httpx.Client(base_url=server.url, timeout=10) as client:
            start = client.get("/v1/robot", headers=AUTH_OP).json()
            assert start["place"] == "meeting_room" and not start["moving"]
            assert len(start["particles"]) > 100  # AMCL is on from the start
            watcher.start()
            iid = _submit(client)
            kinds = [kind for _, kind, _ in sse(client, f"/v1/instructions/{iid}/events", LEE)]
            stop.set()
            watcher.join()
            assert kinds[-1] == "instruction_ended"
            body = client.get(f"/v1/instructions/{iid}", headers=AUTH_LEE).json()
            assert body["status"] == "done", body["summary"]
            [listed] = client.get("/v1/instructions", headers=AUTH_LEE).json()["items"]
            assert listed["steps"] == body["steps"] == len(body["trace"]["steps"]) > 3
    finally:
        stop.set()
        server.stop()
    driving = [s for s in seen if s["moving"]]
    assert driving, "never saw the robot driving"
    assert all(s["place"] is None and s["path"] and s["particles"] for s in driving)
    poses = {(round(s["pose"]["x"], 2), round(s["pose"]["y"], 2)) for s in driving}  # type: ignore[index]
    assert len(poses) >= 5, poses  # the pose advances during the drive, not only at its end
    assert seen[-1]["place"] == "desk_03" and seen[-1]["odometer_m"] > 10  # at Lee's desk


def _lock_sim(port: int, data_dir: Path) -> subprocess.Popen[bytes]:
    env = base_env(data_dir, ASSISTANTX_LOCK_SHARED_KEY=SHARED_KEY)
    cmd = [sys.executable, "-m", "assistantx", "lock-sim", "--port", str(port)]
    cmd += ["--lock-id", "locker-9"]
    process = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE)
    assert process.stdout is not None
    line = process.stdout.readline().decode()
    assert "listening" in line, line
    return process


def test_a_handover_through_the_lock_sim_process(tmp_path: Path) -> None:
    lock_port = free_port()
    lock = _lock_sim(lock_port, tmp_path / "data")
    server = None
    try:
        server = serve(
            tmp_path / "data",
            free_port(),
            ASSISTANTX_LOCK="tcp",
            ASSISTANTX_LOCK_PORT=str(lock_port),
            ASSISTANTX_LOCK_ID="locker-9",
            ASSISTANTX_LOCK_SHARED_KEY=SHARED_KEY,
            ASSISTANTX_ROBOT="sim",
        )
        with httpx.Client(base_url=server.url, timeout=10) as client:
            iid = _submit(client)
            events = list(sse(client, f"/v1/instructions/{iid}/events", LEE))
            body = client.get(f"/v1/instructions/{iid}", headers=AUTH_LEE).json()
            assert body["status"] == "done", body["summary"]
            waits = [
                r
                for s in body["trace"]["steps"]
                for r in s["results"]
                if r["action"]["type"] == "wait_in_place"
            ]
            assert len(waits) == 2 and all(r["ok"] for r in waits)  # deposit, then collect
            locker = client.get("/v1/locker", headers=AUTH_OP).json()
            assert locker["lock_id"] == "locker-9" and locker["door"] == "closed"
            assert events[-1][1] == "instruction_ended"
    finally:
        if server is not None:
            server.stop()
        lock.terminate()
        lock.wait(10)
        assert lock.stdout is not None
        lock.stdout.close()


def test_tcp_lock_without_keys_fails_at_start(tmp_path: Path) -> None:
    env = base_env(tmp_path / "data", ASSISTANTX_LOCK="tcp")
    cmd = [sys.executable, "-m", "assistantx", "serve", "--port", str(free_port())]
    done = subprocess.run(cmd, env=env, capture_output=True, timeout=60, check=False)
    assert done.returncode != 0
    assert b"ASSISTANTX_LOCK_SHARED_KEY" in done.stdout + done.stderr
