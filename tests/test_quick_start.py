"""The README's "Quick start", pasted into a shell, works line by line: the test takes the exact
lines of its shell block and runs them in bash against a fresh ``assistantx serve``.

What the test provides is what the README asks for before the block: a ``.venv`` with the app
installed (a link to the virtualenv running the tests, with this checkout's code first on
``PYTHONPATH``). It sets ``PORT`` (a free port), which the lines themselves read, and
``ASSISTANTX_SPEEDUP`` so the simulated office runs faster; it runs them in an empty folder so
the service's data goes there. Nothing else in the lines is changed.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import httpx
import pytest

from helpers.eventually import eventually_sync
from helpers.servers import free_port

ROOT = Path(__file__).resolve().parents[1]


def quick_start_lines() -> str:
    readme = (ROOT / "README.md").read_text()
    section = readme.split("\n## Quick start\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```sh\n(.*?)```", section, re.S)
    assert len(blocks) == 1, "the quick start has one shell block to paste"
    return str(blocks[0])


def test_the_quick_start_is_at_the_top_of_the_readme() -> None:
    headings = re.findall(r"^## (.+)$", (ROOT / "README.md").read_text(), re.M)
    assert headings[0] == "Quick start"


@pytest.mark.slow
def test_the_quick_start_lines_run_as_pasted(tmp_path: Path) -> None:
    lines = quick_start_lines()
    assert "${PORT:-8000}" in lines  # what the test chooses, through the lines' own variable
    venv = Path(sys.executable).parent.parent
    (tmp_path / ".venv").symlink_to(venv)
    port = free_port()
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    env.update(
        PORT=str(port),
        ASSISTANTX_SPEEDUP="50",
        PYTHONPATH=str(ROOT / "src"),
    )
    # The pasted lines leave the service running (the README stops it with `kill %1`).
    # Output goes to files: the service keeps the shell's stdout open after the lines end.
    script = lines
    stdout, stderr = tmp_path / "stdout.txt", tmp_path / "stderr.txt"
    # In a session of its own: the service started with `&` shares the shell's process group,
    # so the whole group is stopped at the end, also when the lines time out or fail (killing
    # only the printed pid, which a failed or timed-out run never printed, left it running).
    with stdout.open("w") as out_file, stderr.open("w") as err_file:
        process = subprocess.Popen(
            ["bash", "-e", "-o", "pipefail", "-c", script],
            cwd=tmp_path,
            env=env,
            stdout=out_file,
            stderr=err_file,
            start_new_session=True,
        )
    try:
        process.wait(timeout=240)
        out = stdout.read_text()
        assert process.returncode == 0, (out[-3000:], stderr.read_text()[-3000:])
        events = re.findall(r"^event: (\S+)$", out, re.M)
        assert events[0] == "instruction_started" or "instruction_started" in events, events
        assert events[-1] == "instruction_ended", events
        record = json.loads(next(line for line in out.splitlines() if line.startswith('{"id"')))
        assert record["status"] == "done" and record["outcome"] == "done", record
        assert record["requester"] == "lee"
        dashboard = f"dashboard: http://127.0.0.1:{port}/ (paste the token "
        assert dashboard in out
        page = httpx.get(f"http://127.0.0.1:{port}/", timeout=10)
        assert page.status_code == 200 and "<html" in page.text.lower()
        assert (tmp_path / "data" / "journal.sqlite3").is_file()  # its data went where it ran
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGTERM)
        process.wait(timeout=30)
        eventually_sync(lambda: not _group_alive(process.pid), what="the service to stop")


def _group_alive(pgid: int) -> bool:
    try:
        os.killpg(pgid, 0)
    except ProcessLookupError:
        return False
    return True
