"""Person names on the command line (``--as``, ``--unavailable``) resolve like names a person
types, bad ones get one line; ``run --json`` prints only JSON; ``sim`` explains itself; and
``lock-sim`` with no key configured agrees with ``serve`` on the same data folder. Every
command runs as a real subprocess."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import httpx
import pytest

from helpers.processes import wait_ready
from helpers.servers import free_port

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow

STAPLER = "bring me a stapler"


def _env(**extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    env.update(extra)
    return env


def _cli(*args: str, stdin: str = "", **env: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "assistantx", *args],
        input=stdin,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
        env=_env(**env),
    )


def _one_line_error(out: subprocess.CompletedProcess[str]) -> str:
    assert out.returncode == 2, (out.stdout, out.stderr)
    assert "Traceback" not in out.stderr
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1, out.stderr
    return lines[0]


def test_run_takes_names_for_the_unavailable_and_prints_only_json() -> None:
    out = _cli("run", "--as", "Lee", "--unavailable", "Zhang, Mr Wang", "--json", STAPLER)
    assert "Traceback" not in out.stderr
    summary = json.loads(out.stdout)  # the whole of stdout is the one object
    assert summary["requester"] == "lee"
    assert summary["outcome"] in ("done", "unachievable")
    asked = {a.get("contact") for a in summary["actions"] if a["type"] == "inquire"}
    sent_codes = {a.get("contact") for a in summary["actions"] if a["type"] == "send_qr"}
    # Both absent owners are asked (the assistant does not know who is away) but nobody
    # absent is sent to hand anything over.
    assert not sent_codes & {"zhang", "wang"}, summary["actions"]
    assert asked, summary["actions"]
    assert "instruction ins-1 from lee" in out.stderr  # the readable trace went to stderr


def test_the_unavailable_change_the_run() -> None:
    present = json.loads(_cli("run", "--as", "lee", "--json", "--quiet", STAPLER).stdout)
    absent = json.loads(
        _cli(
            "run", "--as", "lee", "--unavailable", "ZHANG,wang", "--json", "--quiet", STAPLER
        ).stdout
    )
    assert present["actions"] != absent["actions"]


def test_a_misspelt_unavailable_person_gets_one_line() -> None:
    line = _one_line_error(_cli("run", "--as", "lee", "--unavailable", "zhnag", STAPLER))
    assert line.startswith("error: Unknown person 'zhnag'. Did you mean")
    assert "'zhang'" in line


def test_an_unknown_requester_is_offered_only_people() -> None:
    line = _one_line_error(_cli("run", "--as", "nobody", STAPLER))
    assert line.startswith("error: Unknown person 'nobody'.")
    assert "food" not in line  # an item type, not a person
    line = _one_line_error(_cli("run", "--as", "wnag", STAPLER))
    assert "Did you mean 'wang'" in line


def test_sim_takes_names_for_the_unavailable() -> None:
    script = 'inquire contact=wang question="Do you have a stapler?"\nwait timeout_s=60\n'
    out = _cli("sim", "--as", "lee", "--unavailable", "Wang", stdin=script)
    assert out.returncode == 0, out.stderr
    assert "Traceback" not in out.stderr
    assert "wang:" not in out.stdout  # away: no answer
    answered = _cli("sim", "--as", "lee", stdin=script)
    assert "wang:" in answered.stdout
    line = _one_line_error(_cli("sim", "--unavailable", "nobody,wang"))
    assert line.startswith("error: Unknown person 'nobody'.")


def test_sim_resolves_the_requester_once_with_one_line_for_a_stranger() -> None:
    line = _one_line_error(_cli("sim", "--as", "nobody"))
    assert line.startswith("error: Unknown person 'nobody'.")
    out = _cli("sim", "--as", "Mr Lee", stdin=":quit\n")
    assert out.returncode == 0, out.stderr
    assert "requester Lee" in out.stdout


def test_sim_has_help() -> None:
    out = _cli("sim", stdin="help\n")
    assert out.returncode == 0, out.stderr
    assert "error" not in out.stdout
    assert "inquire contact=" in out.stdout and ":goal" in out.stdout
    assert "inquire contact=" in _cli("sim", "--help").stdout


@pytest.fixture
def processes() -> Iterator[list[subprocess.Popen[str]]]:
    started: list[subprocess.Popen[str]] = []
    yield started
    for process in started:
        process.terminate()
        try:
            process.wait(10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait(10)
        if process.stdout is not None:
            process.stdout.close()


def test_lock_sim_without_a_key_shares_the_services_key(
    tmp_path: Path, processes: list[subprocess.Popen[str]]
) -> None:
    data = tmp_path / "data"
    lock_port, port = free_port(), free_port()
    env = _env(
        ASSISTANTX_DATA_DIR=str(data),
        ASSISTANTX_LOCK_PORT=str(lock_port),
        ASSISTANTX_LOCK="tcp",
        ASSISTANTX_OPERATOR_TOKEN="operator-token-for-the-lock-test",
    )
    lock = subprocess.Popen(
        [sys.executable, "-m", "assistantx", "lock-sim"],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    processes.append(lock)
    assert lock.stdout is not None
    first = lock.stdout.readline()
    assert "listening on" in first, first + lock.stdout.read()
    assert (data / "lock-keys.json").exists()

    with (tmp_path / "serve.log").open("w") as log:  # the child keeps its own descriptor
        serve = subprocess.Popen(
            [sys.executable, "-m", "assistantx", "serve", "--port", str(port)],
            env=env,
            stdout=log,
            stderr=subprocess.STDOUT,
            text=True,
        )
    processes.insert(0, serve)  # stopped before the lock
    try:
        wait_ready(serve, f"http://127.0.0.1:{port}/readyz", timeout_s=60, interval_s=0.2)
    except (AssertionError, RuntimeError) as exc:
        raise AssertionError((tmp_path / "serve.log").read_text()) from exc
    # The service reached the lock over the authenticated link: it reports the door.
    status = httpx.get(
        f"http://127.0.0.1:{port}/v1/locker",
        headers={"Authorization": "Bearer operator-token-for-the-lock-test"},
        timeout=5,
    )
    assert status.status_code == 200, status.text
