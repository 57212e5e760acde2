"""10,000 instructions through the served process: resident memory flat, restart fast.

Starts ``python -m assistantx serve`` on a fresh data folder (SQLite journal, the kinematic
robot by default, simulated colleagues, the embedded reasoner, simulated time sped up) and
POSTs ``--n`` instructions to ``/v1/instructions``, keeping ``--window`` of them queued or
running: in turn, one of the 30 base instructions of ``dataset/base_instructions.yaml``
(the robot fetches, delivers, prints ...), a request for something the office does not offer
(declined in words) and an unclear one (the robot asks its requester in words, then gives
up). The service's own ``assistantx_instructions`` gauge (read from the journal) tells when
they ended. The server's resident memory (``VmRSS`` in ``/proc/PID/status``) is sampled
after ``--first`` instructions ended and after every ``--every`` more; growth is the last
sample against the one after ``--first``. Then the server is stopped with SIGINT and a new
``serve`` started on the same data folder: its own user + system CPU-seconds and the wall
time until ``/readyz`` answers, and a GET of the first instruction (read back from that
journal). The run is bounded: nothing more is submitted after ``--max-min`` minutes, what
runs then gets three more minutes to end, and the figures say how many ended.

    python bench/instructions_10k.py [--n 10000] [--first 1000] [--every 1000] [--window 8]
        [--speedup 10000] [--robot sim|navigator] [--max-min 25] [--restarts 1]
        [--keep DIR | --restart-only DIR] [--bytecode | --no-bytecode]

``--restarts N`` starts the second ``serve`` N times on the journal, one after the other, and
reports each and their median (one restart's wall time moves with the machine's load).
``--keep DIR`` leaves the data folder (journal included) at DIR, so the restart can be
measured again later with ``--restart-only DIR``, which submits nothing. By default the
servers share a bytecode cache beside the data folder, as an installed package has one;
``--no-bytecode`` runs with the environment's bytecode settings as they are.

Targets (issue 26): RSS growth after the first 1,000 <= 10%; restart to ready <= 3 s.
Last line: one JSON object.
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import httpx
import yaml

ROOT = Path(__file__).resolve().parents[1]
BASES = ROOT / "dataset" / "base_instructions.yaml"
TOKEN = "bench-operator-token-10k-0000001"
TICKS = os.sysconf("SC_CLK_TCK")
RSS_GROWTH_TARGET_PCT = 10.0
RESTART_TARGET_S = 3.0
ACTIVE = ("queued", "running")
POLL_S = 0.1
DRAIN_S = 180.0  # after --max-min: how long the last instructions may take to end

# Requests the office has no service for (answered with a decline in words) and unclear ones
# (the robot asks its requester what they mean), each from one of the office's people.
DECLINED = [
    ("lee", "book the meeting room for three o'clock"),
    ("zhang", "get me a sandwich pls"),
    ("chen", "can u book me a taxi"),
]
UNCLEAR = [
    ("wang", "bring me the thing"),
    ("mao", "hello"),
]


def workload() -> list[tuple[str, str, str]]:
    """(kind, requester, text) in the order they are submitted, cycled."""
    bases = yaml.safe_load(BASES.read_text(encoding="utf-8"))["instructions"]
    out: list[tuple[str, str, str]] = []
    for i, base in enumerate(bases):
        out.append(("robot", base["requester"], base["text"]))
        out.append(("declined", *DECLINED[i % len(DECLINED)]))
        out.append(("unclear", *UNCLEAR[i % len(UNCLEAR)]))
    return out


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _proc_status(pid: int) -> dict[str, float]:
    """VmRSS and VmHWM (the peak) in MB."""
    out = {}
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        key, _, value = line.partition(":")
        if key in ("VmRSS", "VmHWM"):
            out[key] = int(value.split()[0]) / 1024
    return out


def process_cpu_s(pid: int) -> float:
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / TICKS


def _journal_mb(data: Path) -> float:
    files = [data / "journal.sqlite3", data / "journal.sqlite3-wal"]
    return sum(f.stat().st_size for f in files if f.exists()) / 2**20


@dataclass
class Server:
    process: subprocess.Popen[bytes]
    url: str
    started: float
    log: Path

    @classmethod
    def start(cls, data: Path, args: argparse.Namespace, log: Path) -> Server:
        port = _free_port()
        env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
        if args.bytecode:
            # As an installed package is (pip compiles it): the first start writes the
            # bytecode, the restart reads it, where PYTHONDONTWRITEBYTECODE would have every
            # start compile every module again (about a CPU-second)
            env.pop("PYTHONDONTWRITEBYTECODE", None)
            env["PYTHONPYCACHEPREFIX"] = str(data.parent / "pycache")
        env.update(
            ASSISTANTX_DATA_DIR=str(data),
            ASSISTANTX_OPERATOR_TOKEN=TOKEN,
            ASSISTANTX_SPEEDUP=str(args.speedup),
            ASSISTANTX_ROBOT=args.robot,
            ASSISTANTX_ROBOT_LOCALIZE="false",
            # Simulated time x10,000: the default hour would end a queued one after 0.36 s.
            ASSISTANTX_INSTRUCTION_DEADLINE_S=str(30 * 24 * 3600),
            # A few people send thousands: far beyond a person's per-minute bound.
            ASSISTANTX_INSTRUCTIONS_PER_MINUTE="0",
            # A QR code lives in real time (the lock's clock), the rest in simulated time
            # x10,000: at the default 15 minutes every code of most of the run would be
            # alive at the end (a real office sends a handful in 15 minutes). One minute
            # still outlasts any hand-over here by far.
            ASSISTANTX_LOCK_CODE_EXPIRY_MIN="1",
        )
        cmd = [sys.executable, "-m", "assistantx", "serve", "--port", str(port)]
        started = time.perf_counter()
        with log.open("ab") as out:
            process = subprocess.Popen(cmd, env=env, stdout=out, stderr=subprocess.STDOUT)
        return cls(process, f"http://127.0.0.1:{port}", started, log)

    def wait_ready(self, client: httpx.Client, limit_s: float = 300) -> float:
        """Wall seconds from the start until /readyz answers 200."""
        while time.perf_counter() - self.started < limit_s:
            if self.process.poll() is not None:
                raise RuntimeError(f"serve exited with {self.process.returncode}; see {self.log}")
            try:
                if client.get(f"{self.url}/readyz").status_code == 200:
                    return time.perf_counter() - self.started
            except httpx.TransportError:
                pass
            time.sleep(0.02)
        raise RuntimeError(f"serve was not ready after {limit_s} s; see {self.log}")

    def stop(self, limit_s: float = 60) -> float:
        """SIGINT, as Ctrl-C; wall seconds until the process exited."""
        started = time.perf_counter()
        self.process.send_signal(signal.SIGINT)
        try:
            self.process.wait(limit_s)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
            raise RuntimeError(f"serve still running {limit_s} s after SIGINT") from None
        return time.perf_counter() - started


@dataclass
class Drive:
    """What the load phase saw."""

    samples: list[dict[str, float]] = field(default_factory=list)
    submitted: int = 0
    ended: int = 0
    first_id: str | None = None
    statuses: dict[str, int] = field(default_factory=dict)
    rejected: int = 0  # POSTs answered other than 202


def _statuses(client: httpx.Client, url: str) -> dict[str, int]:
    text = client.get(f"{url}/metrics").text
    out: dict[str, int] = {}
    for line in text.splitlines():
        if line.startswith('assistantx_instructions{status="'):
            status = line.split('"')[1]
            out[status] = int(float(line.rsplit(" ", 1)[1]))
    return out


def drive(server: Server, client: httpx.Client, args: argparse.Namespace, data: Path) -> Drive:
    work = workload()
    run = Drive()
    marks = list(range(args.first, args.n + 1, args.every))
    started = time.perf_counter()
    cpu_at_start = process_cpu_s(server.process.pid)
    deadline = started + 60 * args.max_min
    active = 0
    while True:
        now = time.perf_counter()
        while run.submitted < args.n and active < args.window and now < deadline:
            _, requester, text = work[run.submitted % len(work)]
            response = client.post(
                f"{server.url}/v1/instructions", json={"requester": requester, "text": text}
            )
            if response.status_code != 202:
                run.rejected += 1
                print(f"POST answered {response.status_code}: {response.text[:200]}", flush=True)
            elif run.first_id is None:
                run.first_id = response.json()["id"]
            run.submitted += 1
            active += 1
        time.sleep(POLL_S)
        run.statuses = _statuses(client, server.url)
        active = sum(run.statuses.get(s, 0) for s in ACTIVE)
        run.ended = sum(run.statuses.values()) - active
        while marks and run.ended >= marks[0]:
            marks.pop(0)
            memory = _proc_status(server.process.pid)
            elapsed = time.perf_counter() - started
            sample = {
                "ended": run.ended,
                "rss_mb": round(memory["VmRSS"], 1),
                "hwm_mb": round(memory["VmHWM"], 1),
                "journal_mb": round(_journal_mb(data), 1),
                "wall_s": round(elapsed, 1),
                "server_cpu_s": round(process_cpu_s(server.process.pid) - cpu_at_start, 1),
            }
            run.samples.append(sample)
            print(json.dumps(sample), flush=True)
        if active == 0 and (run.submitted >= args.n or time.perf_counter() >= deadline):
            return run
        if time.perf_counter() >= deadline + DRAIN_S:  # what still runs is counted, not waited
            print(f"{active} instructions still queued or running after the drain", flush=True)
            return run


@dataclass
class Restart:
    """One ``serve`` started on the journal of the run: until ready, and the first
    instruction read back."""

    wall_s: float
    cpu_s: float
    rss_mb: float
    read_back: bool

    def as_json(self) -> dict[str, object]:
        return {
            "wall_s": round(self.wall_s, 2),
            "cpu_s": round(self.cpu_s, 2),
            "rss_mb": round(self.rss_mb, 1),
            "first_instruction_read_back": self.read_back,
        }


def restart(data: Path, args: argparse.Namespace, client: httpx.Client, first_id: str) -> Restart:
    again = Server.start(data, args, args.log)
    try:
        wall_s = again.wait_ready(client)
        cpu_s = process_cpu_s(again.process.pid)
        rss_mb = _proc_status(again.process.pid)["VmRSS"]
        first = client.get(f"{again.url}/v1/instructions/{first_id}")
        read_back = first.status_code == 200 and first.json()["status"] not in ACTIVE
    finally:
        again.stop()
    return Restart(wall_s, cpu_s, rss_mb, read_back)


def restarts(
    data: Path, args: argparse.Namespace, client: httpx.Client, first_id: str
) -> dict[str, object]:
    """``--restarts`` starts on the journal, one after the other: each, and their medians."""
    runs = [restart(data, args, client, first_id) for _ in range(max(1, args.restarts))]
    wall_s = statistics.median(r.wall_s for r in runs)
    cpu_s = statistics.median(r.cpu_s for r in runs)
    return {
        "journal_mb": round(_journal_mb(data), 1),
        "restart_wall_s": round(wall_s, 2),
        "restart_cpu_s": round(cpu_s, 2),
        "restart_rss_mb": round(runs[0].rss_mb, 1),
        "restarts": [r.as_json() for r in runs],
        "restart_ok": cpu_s <= RESTART_TARGET_S and wall_s <= RESTART_TARGET_S,
        "first_instruction_read_back": all(r.read_back for r in runs),
    }


FIRST_ID_FILE = "bench-first-instruction-id"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=10_000)
    parser.add_argument("--first", type=int, default=1000)
    parser.add_argument("--every", type=int, default=1000)
    parser.add_argument("--window", type=int, default=8, help="instructions in flight")
    parser.add_argument("--speedup", type=float, default=10_000.0)
    parser.add_argument("--robot", choices=["sim", "navigator"], default="sim")
    parser.add_argument("--max-min", type=float, default=25.0, help="stop submitting after")
    parser.add_argument("--restarts", type=int, default=1, help="starts on the journal")
    parser.add_argument("--bytecode", action=argparse.BooleanOptionalAction, default=True)
    parser.add_argument("--keep", type=Path, help="leave the data folder here")
    parser.add_argument("--restart-only", type=Path, help="a folder --keep left: restarts only")
    parser.add_argument("--log", type=Path, default=Path("results/bench/instructions_10k.log"))
    args = parser.parse_args()
    if args.first > args.n:
        parser.error("--first must be at most --n")
    if args.keep is not None and args.keep.exists():
        parser.error(f"--keep {args.keep}: already exists")
    args.log.parent.mkdir(parents=True, exist_ok=True)
    args.log.write_bytes(b"")
    headers = {"Authorization": f"Bearer {TOKEN}"}
    if args.restart_only is not None:
        data = args.restart_only / "data"
        first_id = (args.restart_only / FIRST_ID_FILE).read_text(encoding="utf-8").strip()
        with httpx.Client(headers=headers, timeout=60) as client:
            again = restarts(data, args, client, first_id)
        again["load_avg_1min"] = round(os.getloadavg()[0], 1)
        print(
            f"restart on {again['journal_mb']} MB of journal: {again['restart_wall_s']} s "
            f"wall, {again['restart_cpu_s']} CPU-s (median of {max(1, args.restarts)})"
        )
        print(json.dumps(again))
        return
    with tempfile.TemporaryDirectory() as tmp, httpx.Client(headers=headers, timeout=60) as client:
        folder = args.keep or Path(tmp)
        data = folder / "data"
        server = Server.start(data, args, args.log)
        try:
            first_ready_s = server.wait_ready(client)
            run = drive(server, client, args, data)
        finally:
            stop_s = server.stop()
        if run.first_id is None:
            raise RuntimeError("no instruction was accepted")
        (folder / FIRST_ID_FILE).write_text(run.first_id, encoding="utf-8")
        again = restarts(data, args, client, run.first_id)
    result: dict[str, object] = {
        "n": run.submitted,
        "ended": run.ended,
        "rejected": run.rejected,
        "statuses": run.statuses,
        "window": args.window,
        "speedup": args.speedup,
        "robot": args.robot,
        "first_ready_s": round(first_ready_s, 2),
        "samples": run.samples,
    }
    if len(run.samples) >= 2:
        base, last = run.samples[0], run.samples[-1]
        growth = 100 * (last["rss_mb"] / base["rss_mb"] - 1)
        result.update(
            rss_mb_after_first=base["rss_mb"],
            rss_mb_at_end=last["rss_mb"],
            rss_growth_pct=round(growth, 1),
            rss_ok=growth <= RSS_GROWTH_TARGET_PCT,
            server_cpu_s_per_instruction=round(last["server_cpu_s"] / max(1, run.ended), 4),
        )
    result.update(stop_s=round(stop_s, 2), **again, load_avg_1min=round(os.getloadavg()[0], 1))
    print(
        f"{run.ended} instructions ended: RSS {result.get('rss_mb_after_first')} MB after "
        f"{args.first}, {result.get('rss_mb_at_end')} MB at the end "
        f"({result.get('rss_growth_pct')}%); restart to ready {again['restart_wall_s']} s "
        f"wall, {again['restart_cpu_s']} CPU-s"
    )
    print(json.dumps(result))


if __name__ == "__main__":
    main()
