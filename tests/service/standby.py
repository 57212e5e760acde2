"""A replica started while another runs the office: ``assistantx serve`` as a subprocess that
waits as a standby (it answers no HTTP until it holds the office's lease)."""

from __future__ import annotations

import signal
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import httpx
import psycopg

from helpers.eventually import eventually_sync
from service.server import OPERATOR, Server, base_env, free_port

_OPERATOR_HEADERS = {"Authorization": f"Bearer {OPERATOR}"}


@dataclass
class Replica:
    name: str
    process: subprocess.Popen[bytes]
    port: int
    log: Path

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.port}"

    def kill(self) -> None:
        self.process.send_signal(signal.SIGKILL)
        self.process.wait(10)

    def stop(self) -> None:
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGCONT)  # a paused one must hear the SIGTERM
            self.process.terminate()
            try:
                self.process.wait(20)
            except subprocess.TimeoutExpired:
                self.kill()


def start_replica(folder: Path, name: str, env: dict[str, str]) -> Replica:
    """``assistantx serve`` with its own data folder under ``folder``; returns at once."""
    port = free_port()
    log = folder / f"{name}.log"
    with log.open("wb") as out:
        process = subprocess.Popen(
            [sys.executable, "-m", "assistantx", "serve", "--port", str(port)],
            env=base_env(folder / name, ASSISTANTX_REPLICA_ID=name, **env),
            stdout=out,
            stderr=subprocess.STDOUT,
        )
    return Replica(name, process, port, log)


def start_standby(folder: Path, name: str, env: dict[str, str]) -> Replica:
    """``start_replica``, once it says it waits as a standby."""
    replica = start_replica(folder, name, env)
    eventually_sync(
        replica.log.read_text,
        until=lambda text: "waiting as a standby" in text,
        what=f"{name} to wait as a standby",
        timeout_s=60,
    )
    return replica


def rows(url: str, sql: str, args: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """The rows of one query on the replicas' shared database."""
    with psycopg.connect(url, autocommit=True) as db:
        return list(db.execute(sql, args or None).fetchall())  # type: ignore[arg-type]


def holder(replicas: list[Server | Replica]) -> Server | Replica:
    """The replica that runs the office now: the one whose ``/readyz`` answers 200."""

    def ready() -> Server | Replica | None:
        for r in replicas:
            try:
                if httpx.get(f"{r.url}/readyz", timeout=2).status_code == 200:
                    return r
            except httpx.HTTPError:
                continue
        return None

    found = eventually_sync(ready, what="a replica to run the office", timeout_s=60)
    assert found is not None
    return found


def submit(url: str, requester: str, text: str) -> str:
    """The id of an instruction submitted, as the operator, to the replica at ``url``."""
    r = httpx.post(
        f"{url}/v1/instructions",
        headers=_OPERATOR_HEADERS,
        json={"requester": requester, "text": text},
        timeout=10,
    )
    assert r.status_code == 202, r.text
    return str(r.json()["id"])


def ended(replicas: list[Server | Replica], iid: str) -> dict[str, Any]:
    """The instruction's record once it ended, from the live replica that runs the office."""
    last = holder([r for r in replicas if r.process.poll() is None])
    record: dict[str, Any] = eventually_sync(
        lambda: httpx.get(f"{last.url}/v1/instructions/{iid}", headers=_OPERATOR_HEADERS).json(),
        until=lambda rec: rec["status"] not in ("queued", "running"),
        what="the instruction to end",
        timeout_s=120,
    )
    return record


def write_journal(url: str, path: Path, events: str, messages: str) -> None:
    """The shared journal's ``events`` and ``messages`` columns, a row a line, written to
    ``path``: the journal as it ended, for a failure to be read from (tmp_path is kept)."""
    queries = (
        f"SELECT {events} FROM events ORDER BY seq",
        f"SELECT {messages} FROM messages ORDER BY seq",
    )
    path.write_text("\n".join(repr(row) for sql in queries for row in rows(url, sql)))


def holders(server: Server) -> dict[str, str | None]:
    """Who runs each office, as ``server`` answers ``GET /v1/offices`` (ready offices only:
    an office still starting is not run yet)."""
    r = httpx.get(
        f"{server.url}/v1/offices", headers={"Authorization": f"Bearer {OPERATOR}"}, timeout=10
    )
    assert r.status_code == 200, r.text
    return {
        o["id"]: o["replica"] if o["status"] in ("ready", "elsewhere") else None for o in r.json()
    }
