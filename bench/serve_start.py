"""``assistantx serve``: CPU-seconds to ready, a second start on the same data folder (the
map's derived arrays read back from its cache, AMCL's field and the obstacle distances as
memory maps), and the stop after SIGINT.

For each map: a fresh data folder; ``python -m assistantx serve`` started twice on it. Ready
is the first 200 from ``/readyz``; its cost is the server's own user + system CPU time at
that moment (from ``/proc/PID/stat``: wall time on a shared machine mostly measures the
neighbours). That answer comes a little after the service is ready, and the reasoner's
warm-up (a thread started at ready) runs meanwhile and is counted too; the service also
logs its own CPU time at the moment it became ready (``ready_cpu_s_self``, read from its
log). Then SIGINT (``--signal TERM``: SIGTERM, as a supervisor stops it): the seconds until
the process exited, and whether any process it had started (the planning worker,
multiprocessing's resource tracker) was still running.
The office map is the repository's; "warehouse" is nav2's (maps/nav2, 30 x 50 m at 3 cm,
the largest there), with anchors for the office's places spread over its free space.

Bytecode: an installed package is byte-compiled (pip does it), but a checkout run with
PYTHONDONTWRITEBYTECODE (set on the team's machines) compiles every module it imports at
every start, about a CPU-second more. With ``--bytecode`` (the default) the servers write and
read bytecode under a temporary PYTHONPYCACHEPREFIX, filled by one start on a throw-away data
folder first (not counted); ``--no-bytecode`` measures the environment as it is.

Each figure of one start varies by a few tenths of a CPU-second with the machine's load;
``--repeat N`` starts N times after the first on the same data folder ("second": the
median of those, with each run listed), and ``--fresh N`` makes N first starts, each on a
data folder of its own ("first": their median; the later starts use the last folder).

    python bench/serve_start.py [--maps office,warehouse] [--localize | --no-localize]
                                [--bytecode | --no-bytecode] [--repeat N] [--fresh N]
                                [--signal INT | TERM]

Last line: one JSON object.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import httpx
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from assistantx.core.office import load_office
from assistantx.nav.anchor_check import place_anchors
from assistantx.nav.anchors import save_anchors
from assistantx.nav.costmap import Costmap
from assistantx.nav.occupancy_map import load_map
from helpers.children import descendants, still_running

ROOT = Path(__file__).resolve().parents[1]
MAPS = {"office": ROOT / "maps" / "office.yaml", "warehouse": ROOT / "maps/nav2/warehouse.yaml"}
TICKS = os.sysconf("SC_CLK_TCK")
# The service's own count at ready (service/app.py logs it at INFO).
_SELF_COUNTED = re.compile(r"ready .*after ([0-9.]+) CPU-s")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _cpu_s(pid: int) -> float:
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / TICKS  # utime + stime


def _anchors_for(map_yaml: Path, out: Path) -> Path:
    office = load_office()
    placed = place_anchors(
        Costmap.inflate(load_map(map_yaml)), len(office.locations), np.random.default_rng(11)
    )
    ids = (loc.id for loc in office.locations)
    save_anchors(dict(zip(ids, placed.values(), strict=True)), out)
    return out


def _env(base: dict[str, str], data_dir: Path, map_yaml: Path, localize: bool) -> dict[str, str]:
    return base | {
        "ASSISTANTX_DATA_DIR": str(data_dir),
        "ASSISTANTX_OPERATOR_TOKEN": "bench-operator-token-000000001",
        "ASSISTANTX_ROBOT_LOCALIZE": str(localize).lower(),
        "ASSISTANTX_MAP": str(map_yaml),
    }


def start_once(
    env: dict[str, str], log: Path, stop: signal.Signals = signal.SIGINT
) -> dict[str, object]:
    port = _free_port()
    # -v: the service logs its own CPU time at ready (INFO), read back from the log below
    cmd = [sys.executable, "-m", "assistantx", "-v", "serve"]
    cmd += ["--host", "127.0.0.1", "--port", str(port)]
    began = time.perf_counter()
    logged_before = log.stat().st_size if log.exists() else 0
    with log.open("ab") as out:
        process = subprocess.Popen(cmd, env=env, stdout=out, stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{port}/readyz"
    while True:
        if process.poll() is not None:
            raise RuntimeError(f"serve exited with {process.returncode}; see {log}")
        try:
            if httpx.get(url, timeout=5).status_code == 200:
                break
        except httpx.TransportError:
            pass
        time.sleep(0.01)  # finer than the start: the warm-up after ready is not counted
    ready_cpu = _cpu_s(process.pid)
    ready_wall = time.perf_counter() - began
    children = [child.pid for child in descendants(process.pid)]
    process.send_signal(stop)
    stopping = time.perf_counter()
    try:
        process.wait(60)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait(10)
    stop_s = time.perf_counter() - stopping
    time.sleep(0.5)  # an orphan would still be running by now; a worker ending is quicker
    left = still_running(children)
    for pid in left:  # ours: do not leave them to the machine
        os.kill(pid, signal.SIGKILL)
    with log.open("rb") as written:
        written.seek(logged_before)
        own = _SELF_COUNTED.search(written.read().decode(errors="replace"))
    return {
        "ready_cpu_s": round(ready_cpu, 2),
        "ready_cpu_s_self": float(own.group(1)) if own else None,
        "ready_wall_s": round(ready_wall, 2),
        "stop_s": round(stop_s, 2),
        "children_at_ready": len(children),
        "children_left": len(left),
    }


def _median_run(runs: list[dict[str, object]]) -> dict[str, object]:
    """The run whose ready CPU is the median (the lower one of an even count)."""
    ranked = sorted(runs, key=lambda run: float(str(run["ready_cpu_s"])))
    return ranked[(len(ranked) - 1) // 2]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--maps", default="office,warehouse")
    parser.add_argument("--localize", action=argparse.BooleanOptionalAction, default=True)
    parser.add_argument("--bytecode", action=argparse.BooleanOptionalAction, default=True)
    parser.add_argument("--repeat", type=int, default=1, help="starts after the first")
    parser.add_argument("--fresh", type=int, default=1, help="first starts, each on a new folder")
    parser.add_argument("--signal", default="INT", choices=["INT", "TERM"], help="the stop's")
    args = parser.parse_args()
    results: dict[str, dict[str, object]] = {}
    stop = signal.Signals[f"SIG{args.signal}"]
    with tempfile.TemporaryDirectory() as tmp:
        base = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
        if args.bytecode:
            base.pop("PYTHONDONTWRITEBYTECODE", None)
            base["PYTHONPYCACHEPREFIX"] = str(Path(tmp) / "pycache")
            warm = Path(tmp) / "warm-up"
            (warm / "data").mkdir(parents=True)
            start_once(_env(base, warm / "data", MAPS["office"], args.localize), warm / "log")
        for name in args.maps.split(","):
            anchors = None
            if name != "office":
                (Path(tmp) / name).mkdir()
                anchors = _anchors_for(MAPS[name], Path(tmp) / name / "anchors.yaml")
            log = Path(tmp) / name / "server.log"
            firsts = []
            for attempt in range(max(1, args.fresh)):  # each on an empty data folder
                data_dir = Path(tmp) / name / f"data-{attempt}"
                data_dir.mkdir(parents=True)
                env = _env(base, data_dir, MAPS[name], args.localize)
                if anchors is not None:
                    env["ASSISTANTX_MAP_ANCHORS"] = str(anchors)
                firsts.append(start_once(env, log, stop))
            first = _median_run(firsts)
            later = [start_once(env, log, stop) for _ in range(max(1, args.repeat))]
            second = _median_run(later)
            results[name] = {"first": first, "second": second}
            if len(firsts) > 1:
                results[name]["first_ready_cpu_s"] = [run["ready_cpu_s"] for run in firsts]
            if len(later) > 1:
                results[name]["later_ready_cpu_s"] = [run["ready_cpu_s"] for run in later]
                results[name]["later_ready_cpu_s_self"] = [run["ready_cpu_s_self"] for run in later]
            print(
                f"{name}: ready {first['ready_cpu_s']} CPU-s (wall {first['ready_wall_s']} s), "
                f"second start {second['ready_cpu_s']} CPU-s; by the service's own count "
                f"{first['ready_cpu_s_self']} / {second['ready_cpu_s_self']}; "
                f"stop {first['stop_s']} / {second['stop_s']} s; "
                f"processes left {first['children_left']} / {second['children_left']}"
            )
    summary = {"maps": results, "bytecode": args.bytecode, "signal": args.signal}
    print(json.dumps(summary | {"load_avg_1min": round(os.getloadavg()[0], 1)}))


if __name__ == "__main__":
    main()
