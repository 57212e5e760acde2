"""``bin/assistantx`` runs the command from the project's virtualenv, so a newcomer after
``make run`` gets the CLI without activating anything, and a clear line when it is not
installed yet (not bash's "command not found")."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SHIM = ROOT / "bin" / "assistantx"


def _shim(venv: Path, *args: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "VENV": str(venv)}
    return subprocess.run(
        [str(SHIM), *args], env=env, capture_output=True, text=True, timeout=120, check=False
    )


def test_the_shim_runs_the_venvs_command() -> None:
    venv = Path(sys.executable).parent.parent  # the venv running the tests has assistantx
    out = _shim(venv, "office", "show")
    assert out.returncode == 0, out.stderr
    assert "Lee" in out.stdout


def test_without_a_venv_it_says_to_install(tmp_path: Path) -> None:
    out = _shim(tmp_path / "nowhere", "office", "show")
    assert out.returncode == 127
    assert out.stderr.strip() == (
        f"assistantx is not installed in {tmp_path / 'nowhere'} yet: "
        f"run 'make install' (or 'make run') in {ROOT} first"
    )
