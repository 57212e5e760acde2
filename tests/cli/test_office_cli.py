"""The one-shot CLI, run as a real subprocess."""

from __future__ import annotations

import subprocess
import sys

import pytest

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow


def _cli(*args: str, stdin: str = "") -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "assistantx", *args],
        input=stdin,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


def test_office_show_lists_the_locations() -> None:
    out = _cli("office", "show")
    assert out.returncode == 0, out.stderr
    assert "23 locations: 16 workstations, 7 facilities" in out.stdout
    assert "hu" in out.stdout and "stapler*" in out.stdout


def test_office_show_reports_a_bad_file(tmp_path: object) -> None:
    out = _cli("office", "show", "--office", "/nonexistent/office.yaml")
    assert out.returncode == 2
    assert "/nonexistent/office.yaml: file: cannot be read" in out.stdout


def test_sim_script_drives_a_hand_over() -> None:
    script = "\n".join(
        [
            'inquire contact=zhang question="Do you have a stapler?"',
            "wait timeout_s=60",
            'inform contact=zhang content="The robot comes for your stapler"',
            "move place=zhang",
            "send_qr contact=zhang item=stapler:zhang",
            "wait_in_place person=zhang",
            "move place=lee",
            "send_qr contact=lee item=stapler:zhang purpose=collect",
            "wait_in_place person=lee",
            ':goal {"holds": ["lee", "stapler:zhang"]}',
            "inform contact=nobody content=x",
        ]
    )
    out = _cli("sim", "--as", "lee", stdin=script)
    assert out.returncode == 0, out.stderr
    assert "zhang: Yes, I have a stapler" in out.stdout
    assert 'goal {"holds": ["lee", "stapler:zhang"]}: True' in out.stdout
    assert "error: Unknown contact 'nobody'" in out.stdout
