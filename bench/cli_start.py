"""CPU-seconds a command-line command costs, from process start to exit.

Runs each command a few times as a fresh ``python -m assistantx`` process and reads the
child's user + system CPU time from ``resource.getrusage(RUSAGE_CHILDREN)`` (CPU time, not
wall time: on a shared machine the wall clock mostly measures the neighbours). Prints one
line per command with its median, then one JSON object as the last line.

    python bench/cli_start.py [--repeat N]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys

COMMANDS: dict[str, list[str]] = {
    "office show": ["office", "show"],
    "run --help": ["run", "--help"],
    "lock-keys --help": ["lock-keys", "--help"],
    "serve --help": ["serve", "--help"],
    "--help": ["--help"],
}
TARGET_OFFICE_SHOW_S = 0.5


def cpu_seconds(argv: list[str]) -> float:
    """User + system CPU seconds of one ``python -m assistantx ARGV`` run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(
        [sys.executable, "-m", "assistantx", *argv],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        check=True,
    )
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="runs per command (default 5)")
    args = parser.parse_args()
    medians: dict[str, float] = {}
    for name, argv in COMMANDS.items():
        runs = [cpu_seconds(argv) for _ in range(args.repeat)]
        medians[name] = round(statistics.median(runs), 3)
        print(f"{name:18} median {medians[name]:.2f} CPU-s (min {min(runs):.2f}, n {len(runs)})")
    load1 = round(os.getloadavg()[0], 1)
    result = {
        "cpu_s_median": medians,
        "load_avg_1min": load1,
        "office_show_target_s": TARGET_OFFICE_SHOW_S,
        "office_show_ok": medians["office show"] <= TARGET_OFFICE_SHOW_S,
    }
    print(json.dumps(result))


if __name__ == "__main__":
    main()
