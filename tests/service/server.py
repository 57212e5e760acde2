"""Start ``python -m assistantx serve`` as a real subprocess on a free 127.0.0.1 port."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path

import httpx

from helpers.processes import wait_ready
from helpers.servers import free_port

HERE = Path(__file__).resolve().parent
OPERATOR = "operator-token-for-tests-0001"
LEE = "lee-token-for-tests-00000001"
ZHANG = "zhang-token-for-tests-000001"
__all__ = ["LEE", "OPERATOR", "ZHANG", "Server", "base_env", "free_port", "serve", "sse", "start"]


def base_env(data_dir: Path, **extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    env.update(
        {
            "ASSISTANTX_DATA_DIR": str(data_dir),
            "ASSISTANTX_OPERATOR_TOKEN": OPERATOR,
            "ASSISTANTX_TOKENS": json.dumps({LEE: "lee", ZHANG: "zhang"}),
            "ASSISTANTX_SPEEDUP": "50",
            # This checkout's code, also where an installed copy elsewhere comes first.
            "PYTHONPATH": os.pathsep.join([str(HERE.parent), str(HERE.parents[1] / "src")]),
        }
    )
    env.update(extra)
    return env


@dataclass
class Server:
    process: subprocess.Popen[bytes]
    url: str
    log: Path

    def kill(self) -> None:
        self.process.send_signal(signal.SIGKILL)
        self.process.wait(10)

    def stop(self) -> None:
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                self.kill()


def start(args: list[str], env: Mapping[str, str], port: int, timeout_s: float = 60.0) -> Server:
    log = Path(env["ASSISTANTX_DATA_DIR"]).parent / f"server-{port}-{time.monotonic_ns()}.log"
    with log.open("wb") as out:  # the child keeps its own copy of the descriptor
        process = subprocess.Popen(args, env=dict(env), stdout=out, stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{port}"
    try:
        wait_ready(process, f"{url}/readyz", timeout_s=timeout_s)
    except AssertionError as exc:
        process.kill()
        process.wait(10)  # reaped here, not left for a later test's garbage collection to warn
        raise RuntimeError(f"{exc}:\n{log.read_text()}") from None
    except RuntimeError as exc:
        raise RuntimeError(f"{exc}:\n{log.read_text()}") from None
    return Server(process, url, log)


def serve(data_dir: Path, port: int, **extra: str) -> Server:
    cmd = [sys.executable, "-m", "assistantx", "serve", "--host", "127.0.0.1", "--port", str(port)]
    return start(cmd, base_env(data_dir, **extra), port)


def sse(
    client: httpx.Client, path: str, token: str, last_id: int | None = None
) -> Iterator[tuple[int, str, dict[str, object]]]:
    """Yield (id, event, data) from an SSE endpoint until the server ends the stream."""
    headers = {"Authorization": f"Bearer {token}"}
    if last_id is not None:
        headers["Last-Event-ID"] = str(last_id)
    with client.stream("GET", path, headers=headers, timeout=30) as response:
        assert response.status_code == 200, response.read()
        event_id, kind, data = 0, "", ""
        for line in response.iter_lines():
            if line.startswith("id: "):
                event_id = int(line[4:])
            elif line.startswith("event: "):
                kind = line[7:]
            elif line.startswith("data: "):
                data = line[6:]
            elif line == "" and data:
                yield event_id, kind, json.loads(data)
                data = ""
