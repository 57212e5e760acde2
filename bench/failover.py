"""Failover of replicas on one PostgreSQL: N instructions in flight, the holder killed 3 times.

Two ``python -m assistantx serve`` replicas (simulated robot and people) share one database
(``--database-url``, else a throwaway cluster like the tests' one, which needs PostgreSQL's
``initdb``). N instructions go to the holder; then, three times, after a random pause the
replica that holds the office is killed with SIGKILL and started again as a standby, so two
replicas run at all times. For each kill: the seconds until the other replica answers
``/readyz`` (the lease's expiry, the standby's next try and its start-up: journal, map,
resuming the unfinished instructions). At the end, counted in the shared journal:

- lost: instructions not ended (done, failed, unachievable, cancelled) within ``--end-timeout`` s;
- duplicated messages: an instruction's outbound message (same chat, same text) or a question
  journaled more than once;
- duplicated codes: more than one code sent for the same instruction, person and purpose.

Both must be 0. Seconds are wall time on whatever machine runs it (a loaded one stretches
them); the lease's time (``--ttl``) bounds the wait for the expiry.

    python bench/failover.py [--instructions 4] [--kills 3] [--ttl 2] [--seed 1] [--replicas 2]

Instructions per minute: the instructions ended over the minutes from the first submission to
the last end (``--kills 0 --replicas 1``, ``2``, ``3`` compare the replica counts: one office
is run by one replica at a time, so the others add failover, not throughput).

Last line: one JSON object.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import httpx
import psycopg

ROOT = Path(__file__).resolve().parents[1]
OPERATOR = "bench-operator-token"
HEADERS = {"Authorization": f"Bearer {OPERATOR}"}
ENDED = {"done", "failed", "unachievable", "cancelled"}  # the journal's final statuses


@dataclass
class Replica:
    name: str
    port: int
    data: Path
    process: subprocess.Popen[bytes] | None = None

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.port}"

    def start(self, env: dict[str, str]) -> None:
        log = (self.data.parent / f"{self.name}.log").open("ab")
        self.process = subprocess.Popen(
            [sys.executable, "-m", "assistantx", "serve", "--port", str(self.port)],
            env={**env, "ASSISTANTX_DATA_DIR": str(self.data), "ASSISTANTX_REPLICA_ID": self.name},
            stdout=log,
            stderr=subprocess.STDOUT,
        )
        log.close()

    def ready(self) -> bool:
        try:
            return httpx.get(f"{self.url}/readyz", timeout=2).status_code == 200
        except httpx.HTTPError:
            return False

    def kill(self) -> None:
        if self.process is not None and self.process.poll() is None:
            self.process.send_signal(signal.SIGKILL)
            self.process.wait(10)

    def stop(self) -> None:
        if self.process is not None and self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(30)
            except subprocess.TimeoutExpired:
                self.kill()


def free_port() -> int:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def wait(condition: Any, what: str, timeout_s: float) -> None:
    deadline = time.monotonic() + timeout_s
    while not condition():
        if time.monotonic() > deadline:
            raise SystemExit(f"gave up waiting for {what} after {timeout_s:.0f} s")
        time.sleep(0.05)


def rows(url: str, sql: str) -> list[tuple[Any, ...]]:
    with psycopg.connect(url, autocommit=True) as db:
        return list(db.execute(sql).fetchall())


def duplicates(url: str) -> tuple[int, int]:
    """(messages, codes) journaled more than once; see the module's docstring."""
    messages = rows(
        url,
        "SELECT count(*) FROM (SELECT 1 FROM messages WHERE direction='out'"
        " GROUP BY coalesce(instruction_id, ''), coalesce(question_id, ''), chat_id, text"
        " HAVING count(*) > 1) AS repeated",
    )[0][0]
    questions = rows(
        url,
        "SELECT count(*) FROM (SELECT 1 FROM messages WHERE question_id IS NOT NULL"
        " AND direction='out' GROUP BY question_id HAVING count(*) > 1) AS repeated",
    )[0][0]
    codes: dict[tuple[str, str, str], int] = {}
    for iid, data in rows(
        url, "SELECT instruction_id, data FROM events WHERE kind='action_result'"
    ):
        result = json.loads(data).get("result") or {}
        action = result.get("action") or {}
        if action.get("type") == "send_qr" and result.get("ok"):
            key = (iid, action["contact"], action.get("purpose", ""))
            codes[key] = codes.get(key, 0) + 1
    for row in rows(
        url,
        "SELECT instruction_id, question_id, chat_id, left(text, 70), count(*) FROM messages"
        " WHERE direction='out' GROUP BY instruction_id, question_id, chat_id, text"
        " HAVING count(*) > 1",
    ):
        print("message sent more than once:", row)
    for key, n in codes.items():
        if n > 1:
            print(f"{n} codes for one instruction, person and purpose:", key)
    return int(messages) + int(questions), sum(1 for n in codes.values() if n > 1)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--instructions", type=int, default=4)
    parser.add_argument("--kills", type=int, default=3)
    parser.add_argument("--ttl", type=float, default=2.0, help="the office lease's seconds")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--replicas", type=int, default=2, help="replicas sharing the office")
    parser.add_argument("--database-url", default=None, help="default: a throwaway cluster")
    parser.add_argument("--end-timeout", type=float, default=300.0)
    args = parser.parse_args()
    rng = random.Random(args.seed)

    cluster = None
    url = args.database_url
    if url is None:
        sys.path.insert(0, str(ROOT / "tests"))
        from helpers.postgres import start_cluster

        cluster = start_cluster()
        url = cluster.new_database()
    work = Path(tempfile.mkdtemp(prefix="assistantx-failover-"))
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    env.update(
        {
            "ASSISTANTX_DATABASE_URL": url,
            "ASSISTANTX_LEASE_TTL_S": str(args.ttl),
            "ASSISTANTX_OPERATOR_TOKEN": OPERATOR,
            # One lock key for all replicas, as the README asks: without it each made its own,
            # and a code sent before a kill was refused by the next replica's lock.
            "ASSISTANTX_LOCK_SHARED_KEY": "the failover bench's shared lock key",
            "ASSISTANTX_ROBOT": "sim",
            "ASSISTANTX_SPEEDUP": "50",
            "ASSISTANTX_SIM_REPLY_DELAY_S": "60",  # 300 makes the questions time out (unachievable)
            "ASSISTANTX_SIM_HANDOVER_DELAY_S": "300",
            "ASSISTANTX_INSTRUCTIONS_PER_MINUTE": "0",
            "PYTHONPATH": str(ROOT / "src"),
        }
    )
    names = [f"replica-{chr(ord('a') + n)}" for n in range(args.replicas)]
    replicas = [Replica(n, free_port(), work / n) for n in names]
    resumes: list[float] = []
    try:
        replicas[0].start(env)
        wait(replicas[0].ready, "the first replica", 180)
        for standby in replicas[1:]:
            standby.start(env)
            log = work / f"{standby.name}.log"
            wait(lambda log=log: "waiting as a standby" in log.read_text(), standby.name, 180)
        if args.kills and len(replicas) < 2:
            raise SystemExit("kills need a standby: --replicas 2 or more")
        ids = []
        submitted = time.monotonic()
        for _ in range(args.instructions):
            r = httpx.post(
                f"{replicas[0].url}/v1/instructions",
                headers=HEADERS,
                json={"requester": "lee", "text": "Please bring me a stapler."},
                timeout=30,
            )
            r.raise_for_status()
            ids.append(str(r.json()["id"]))
        for kill in range(args.kills):
            time.sleep(rng.uniform(0.5, 4.0))  # a random moment in the instructions' run
            holder = next(r for r in replicas if r.ready())
            others = [r for r in replicas if r is not holder]
            holder.kill()
            killed = time.monotonic()
            wait(
                lambda others=others: any(r.ready() for r in others),
                f"a standby after kill {kill + 1}",
                180,
            )
            resumes.append(round(time.monotonic() - killed, 2))
            other = next(r for r in others if r.ready())
            print(f"kill {kill + 1}: {holder.name} killed; {other.name} ready in {resumes[-1]} s")
            log = work / f"{holder.name}.log"
            before = log.read_text().count("waiting as a standby")
            holder.start(env)  # back as the standby
            wait(
                lambda log=log, before=before: (
                    log.read_text().count("waiting as a standby") > before
                ),
                "the killed replica back as the standby",
                180,
            )
        holder = next(r for r in replicas if r.ready())
        deadline = time.monotonic() + args.end_timeout
        statuses: dict[str, str] = {}
        while time.monotonic() < deadline:
            statuses = {
                iid: httpx.get(f"{holder.url}/v1/instructions/{iid}", headers=HEADERS, timeout=30)
                .json()
                .get("status", "missing")
                for iid in ids
            }
            if all(s in ENDED for s in statuses.values()):
                break
            time.sleep(0.5)
        minutes = (time.monotonic() - submitted) / 60
        lost = sum(1 for s in statuses.values() if s not in ENDED)
        dup_messages, dup_codes = duplicates(url)
        ended: dict[str, int] = {}
        for s in statuses.values():
            ended[s] = ended.get(s, 0) + 1
        print(f"instructions: {ended}; lost {lost}")
        print(f"duplicated: messages {dup_messages}, codes {dup_codes}")
    finally:
        for replica in replicas:
            replica.stop()
        if cluster is not None:
            cluster.stop()
    print(
        json.dumps(
            {
                "instructions": args.instructions,
                "replicas": args.replicas,
                "kills": args.kills,
                "instructions_per_minute": round((len(ids) - lost) / minutes, 2),
                "lease_ttl_s": args.ttl,
                "resume_s": resumes,
                "statuses": ended,
                "lost": lost,
                "duplicated_messages": dup_messages,
                "duplicated_codes": dup_codes,
            }
        )
    )


if __name__ == "__main__":
    main()
