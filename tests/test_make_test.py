"""The README's test command, ``make test``, installs everything the suite needs itself, into
the project (never silently into the home folder), and says what it installs."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[1]


def _make_dry_run(*args: str) -> list[str]:
    env = {k: v for k, v in os.environ.items() if k != "SYNAPSE_VENV"}
    out = subprocess.run(
        ["make", "--no-print-directory", "-n", *args],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=True,
    )
    return out.stdout.splitlines()


def _index(lines: list[str], needle: str) -> int:
    found = [i for i, line in enumerate(lines) if needle in line]
    assert found, f"{needle!r} not in:\n" + "\n".join(lines)
    return found[0]


def test_make_test_installs_synapse_and_chromium_before_the_suite() -> None:
    lines = _make_dry_run("test")
    suite = _index(lines, "-m pytest")
    assert _index(lines, ".ci/install-synapse") < suite
    assert _index(lines, ".ci/install-browser") < suite
    assert _index(lines, ".ci/install-postgres") < suite
    # It says what it installs, and where: Synapse inside the project.
    announce = lines[_index(lines, "echo") : suite]
    assert any(f"{ROOT}/.cache/synapse-venv" in line for line in announce), announce
    assert any("Chromium" in line for line in announce), announce


def test_synapse_goes_into_the_project_by_default(tmp_path: Path) -> None:
    # A Python that cannot make a venv stops the script right after it says where it installs,
    # so this checks the default place without installing anything.
    env = {k: v for k, v in os.environ.items() if k != "SYNAPSE_VENV"}
    env.update(SYNAPSE_PYTHON="/bin/false", SYNAPSE_VERSION="0.0.0-never")
    out = subprocess.run(
        ["bash", str(ROOT / ".ci" / "install-synapse")],
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert out.returncode != 0
    assert f"into {ROOT}/.cache/synapse-venv" in out.stderr, out.stderr


def test_ci_runs_exactly_what_the_readme_says() -> None:
    commands = [
        line
        for line in (ROOT / ".ci" / "run").read_text().splitlines()
        if line and not line.startswith("#") and not line.startswith(("set ", "cd "))
    ]
    assert commands == ["make test", "make check"]
    readme = (ROOT / "README.md").read_text()
    assert "make test" in readme and ".cache/synapse-venv" in readme
