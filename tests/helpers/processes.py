"""Waiting for a server started as a subprocess to answer over HTTP."""

from __future__ import annotations

import subprocess

import httpx

from helpers.eventually import eventually_sync


def wait_ready(
    process: subprocess.Popen[bytes] | subprocess.Popen[str],
    url: str,
    *,
    timeout_s: float,
    interval_s: float = 0.1,
) -> None:
    """Until ``url`` answers with a success status. A process that exits first raises
    RuntimeError at once; no answer within ``timeout_s`` raises AssertionError."""

    def answers() -> bool:
        if process.poll() is not None:
            raise RuntimeError(f"{process.args!r} exited with {process.returncode}")
        return httpx.get(url, timeout=2).status_code == 200

    eventually_sync(
        answers,
        what=f"{url} to answer",
        timeout_s=timeout_s,
        interval_s=interval_s,
        ignore=(httpx.TransportError,),
    )
