"""``assistantx sim`` as a newcomer uses it: the help's example works when typed line by line,
goals and places take names as people write them, ``:world`` says who holds what, a plain
sentence is offered to run as an instruction, and a terminal gets a prompt. Every session is a
real subprocess fed on stdin (or a pseudo-terminal)."""

from __future__ import annotations

import os
import pty
import subprocess
import sys

import pytest

from assistantx.cli.sim_cmd import EXAMPLE, PROMPT

# Starts the CLI as a process: not in `make test-fast`.
pytestmark = pytest.mark.slow


def _sim(stdin: str, *args: str) -> list[str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    out = subprocess.run(
        [sys.executable, "-m", "assistantx", "sim", *args],
        input=stdin,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
        env=env,
    )
    assert out.returncode == 0, out.stderr
    assert "Traceback" not in out.stderr
    return out.stdout.splitlines()


def test_the_help_example_typed_line_by_line_fetches_the_stapler() -> None:
    typed = [line.strip() for line in EXAMPLE.splitlines()]
    assert any("purpose=collect" in line for line in typed)
    lines = _sim("\n".join([*typed, ":world"]) + "\n", "--as", "lee")
    assert not [line for line in lines if line.startswith("error") or "FAILED" in line], lines
    # the goal in the example names people in capitals, as a person types them
    assert 'goal {"holds": ["lee", "stapler:zhang"]}: True' in lines
    assert "locker: empty" in lines
    assert "Lee Ming holds: book:lee, document:lee, pen:lee, stapler:zhang" in lines
    assert "Zhang Wei holds: document:zhang" in lines


def test_goals_resolve_names_and_say_when_one_is_unknown() -> None:
    lines = _sim(
        ':goal {"holds": ["LEE", "Stapler:*"]}\n'
        ':goal {"holds": ["Lee Ming", "Zhang\'s stapler"]}\n'
        ':goal {"holds": ["Bob", "stapler:zhang"]}\n'
        ":goal holds lee\n"
    )
    assert 'goal {"holds": ["lee", "stapler:*"]}: False' in lines
    assert 'goal {"holds": ["lee", "stapler:zhang"]}: False' in lines
    assert any(line.startswith("error: Unknown person 'Bob'.") for line in lines), lines
    assert 'error: a goal is JSON after :goal, e.g. :goal {"holds": ["lee", "stapler:zhang"]}' in (
        lines
    )


def test_a_sentence_is_offered_as_an_instruction() -> None:
    lines = _sim("bring me a stapler\ny\nplease print my file\nn\nmove place=Zhang\n")
    offer = (
        "'bring me a stapler' is not an action. Run it as an instruction from Lee Ming "
        "(in a fresh simulated office)? [y/N]"
    )
    assert offer in lines
    assert "instruction ins-1 from lee: 'bring me a stapler'" in lines
    assert any(line.startswith("outcome: done") for line in lines), lines
    assert sum(line.startswith("instruction ins-1") for line in lines) == 1  # "n" ran nothing
    assert not any("expected key=value" in line for line in lines)
    assert lines[-1].endswith("ok: arrived at desk_04 (20.5 m)")


def test_a_terminal_gets_a_prompt() -> None:
    leader, follower = pty.openpty()
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    process = subprocess.Popen(
        [sys.executable, "-m", "assistantx", "sim"],
        stdin=follower,
        stdout=follower,
        stderr=follower,
        env=env,
    )
    os.close(follower)
    os.write(leader, b":quit\n")
    seen = b""
    while True:
        try:
            chunk = os.read(leader, 4096)
        except OSError:  # the terminal closed with the process
            break
        if not chunk:
            break
        seen += chunk
    os.close(leader)
    assert process.wait(60) == 0
    assert PROMPT.encode() in seen, seen
