"""A replica started while another runs the office: ``assistantx serve`` as a subprocess that
waits as a standby (it answers no HTTP until it holds the office's lease)."""

from __future__ import annotations

import signal
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from helpers.eventually import eventually_sync
from service.server import base_env, free_port


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
