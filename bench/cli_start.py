"""CPU-seconds a command-line command costs, from process start to exit.

Runs each command a few times as a fresh ``python -m assistantx`` process and reads the
child's user + system CPU time from ``resource.getrusage(RUSAGE_CHILDREN)`` (CPU time, not
wall time: on a shared machine the wall clock mostly measures the neighbours). Prints one
line per command with its median, then one JSON object as the last line.

With ``--bytecode`` (the default) the commands write and read bytecode under a temporary
PYTHONPYCACHEPREFIX, filled by one run of each first (not counted), as an installed package
is byte-compiled by pip; ``--no-bytecode`` keeps the environment's PYTHONDONTWRITEBYTECODE
(set on the team's machines: each run then compiles the modules it imports).

    python bench/cli_start.py [--repeat N] [--bytecode | --no-bytecode]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile

COMMANDS: dict[str, list[str]] = {
    "office show": ["office", "show"],
    "run --help": ["run", "--help"],
    "lock-keys --help": ["lock-keys", "--help"],
    "serve --help": ["serve", "--help"],
    "--help": ["--help"],
}
TARGET_OFFICE_SHOW_S = 0.5


def cpu_seconds(argv: list[str], env: dict[str, str] | None = None) -> float:
    """User + system CPU seconds of one ``python -m assistantx ARGV`` run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(
        [sys.executable, "-m", "assistantx", *argv],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        check=True,
        env=env,
    )
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="runs per command (default 5)")
    parser.add_argument("--bytecode", action=argparse.BooleanOptionalAction, default=True)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        env = None
        if args.bytecode:
            env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
            env["PYTHONPYCACHEPREFIX"] = tmp
            for argv in COMMANDS.values():
                cpu_seconds(argv, env)
        medians = _medians(args.repeat, env)
    load1 = round(os.getloadavg()[0], 1)
    result = {
        "cpu_s_median": medians,
        "bytecode": args.bytecode,
        "load_avg_1min": load1,
        "office_show_target_s": TARGET_OFFICE_SHOW_S,
        "office_show_ok": medians["office show"] <= TARGET_OFFICE_SHOW_S,
    }
    print(json.dumps(result))


def _medians(repeat: int, env: dict[str, str] | None) -> dict[str, float]:
    medians: dict[str, float] = {}
    for name, argv in COMMANDS.items():
        runs = [cpu_seconds(argv, env) for _ in range(repeat)]
        medians[name] = round(statistics.median(runs), 3)
        print(f"{name:18} median {medians[name]:.2f} CPU-s (min {min(runs):.2f}, n {len(runs)})")
    return medians


if __name__ == "__main__":
    main()
