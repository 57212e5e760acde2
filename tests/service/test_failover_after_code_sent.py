"""kill -9 of the replica that runs the office just after a hand-over code went out: Lee's
collect code is delivered (the message journaled as sent, the code on his phone) and the
replica dies before the step's result is journaled, so the standby replays that step. Lee must
hold exactly one collect code at the end, and it must be the one the lock takes.

The moment is a few milliseconds wide in a real run, so the test holds it open with the
database itself: a trigger on the journal's ``events`` table makes the transaction that
journals the send's result sleep, and the owning replica is killed while it sleeps.

The moment must also stay shut to the simulated Lee of the dying replica: he walks to the
robot one second after his code arrives, and his use of it reaches the shared phones (their
own connection, not the stalled journal) while the lock's report of it dies with the replica.
A test that saw the sleep and killed later than that (a loaded machine) left Lee's phone with a
used code the next replica's lock had never seen used: Lee did not come again and the wait ran
out. So, once the journal sleeps, a write to the phones waits for it too (the sleeping
transaction holds the lock of ``stall_armed``'s row), and the kill may come whenever it comes."""

from __future__ import annotations

import json
from pathlib import Path

import psycopg
import pytest

from helpers.eventually import eventually_sync
from service.server import Server, free_port, serve
from service.standby import Replica, ended, holder, rows, start_standby, submit, write_journal

pytestmark = [pytest.mark.postgres, pytest.mark.slow]

ENV = {
    "ASSISTANTX_LOCK_SHARED_KEY": "the replicas' shared lock key for the tests",
    "ASSISTANTX_LEASE_TTL_S": "3",
    "ASSISTANTX_ROBOT": "sim",
    "ASSISTANTX_SPEEDUP": "20",
    "ASSISTANTX_SIM_HANDOVER_DELAY_S": "20",
}

# Sleeps in the transaction that journals the result of a code sent to Lee, once: the code is
# out, its result not yet written. The test ends the sleeping backend after the kill.
STALL = """
CREATE TABLE stall_armed (armed boolean NOT NULL);
INSERT INTO stall_armed VALUES (true);
CREATE FUNCTION stall_after_lee_code() RETURNS trigger AS $$
BEGIN
  IF NEW.kind = 'action_result' AND NEW.data LIKE '%"type": "send_qr"%'
     AND NEW.data LIKE '%"contact": "lee"%' AND (SELECT armed FROM stall_armed) THEN
    UPDATE stall_armed SET armed = false;
    PERFORM pg_sleep(300);
  END IF;
  RETURN NEW;
END $$ LANGUAGE plpgsql;
CREATE FUNCTION phones_wait_for_the_stall() RETURNS trigger AS $$
BEGIN
  PERFORM armed FROM stall_armed FOR UPDATE;
  RETURN NULL;
END $$ LANGUAGE plpgsql;
"""
TRIGGERS = (
    "CREATE TRIGGER stall BEFORE INSERT ON events FOR EACH ROW"
    " EXECUTE FUNCTION stall_after_lee_code()",
    "CREATE TRIGGER phones_wait BEFORE INSERT OR UPDATE OR DELETE ON sim_phones"
    " FOR EACH STATEMENT EXECUTE FUNCTION phones_wait_for_the_stall()",
)


def run(url: str, sql: str) -> None:
    with psycopg.connect(url, autocommit=True) as db:
        db.execute(sql)  # type: ignore[arg-type]


def sleeping_backend(url: str) -> int | None:
    """The backend stalled in the trigger, once the code's message is journaled as sent."""
    found = rows(url, "SELECT pid FROM pg_stat_activity WHERE wait_event = 'PgSleep'")
    return int(found[0][0]) if found else None


def codes_to(url: str, person: str) -> list[str]:
    """The texts of the code messages that went out to ``person`` (delivered: 'sent')."""
    found = rows(
        url,
        "SELECT body FROM messages WHERE direction='out' AND status='sent'"
        f" AND chat_id='{person}' ORDER BY seq",
    )
    return [
        json.loads(body)["text"]
        for (body,) in found
        if any(a.get("name") == "locker-code.png" for a in json.loads(body)["attachments"])
    ]


def test_a_kill_just_after_a_code_went_out_does_not_send_a_second_code(
    tmp_path: Path, postgres_url: str
) -> None:
    env = {**ENV, "ASSISTANTX_DATABASE_URL": postgres_url}
    first = serve(tmp_path / "replica-a", free_port(), ASSISTANTX_REPLICA_ID="replica-a", **env)
    replicas: list[Server | Replica] = [first]
    try:
        replicas.append(start_standby(tmp_path, "replica-b", env))
        holder(replicas)  # the journal's tables exist once the first replica runs
        with psycopg.connect(postgres_url, autocommit=True) as db:
            db.execute(STALL)
            for trigger in TRIGGERS:
                db.execute(trigger)  # type: ignore[arg-type]
        iid = submit(first.url, "lee", "Please bring me a stapler.")
        stalled = eventually_sync(
            lambda: sleeping_backend(postgres_url),
            what="the result of Lee's code to be journaled (and held)",
            timeout_s=120,
        )
        assert stalled is not None
        assert len(codes_to(postgres_url, "lee")) == 1  # the code is out
        first.kill()
        # Its sleeping journal write lived on alone. A phones write waiting behind it ends
        # with it, uncommitted (its process is gone); the standby's lease waits behind it too
        # (its fence locks the lease's row), so only the sleeper is ended.
        rows(postgres_url, f"SELECT pg_terminate_backend({stalled})")
        run(postgres_url, "DROP TRIGGER stall ON events; DROP TRIGGER phones_wait ON sim_phones")
        record = ended(replicas, iid)
        write_journal(
            postgres_url,
            tmp_path / "journal.txt",
            events="seq, kind, left(data, 400)",
            messages="seq, chat_id, left(text, 50), idempotency_key, status",
        )
        assert record["status"] == "done", record
        assert len(codes_to(postgres_url, "lee")) == 1, codes_to(postgres_url, "lee")
        data = rows(postgres_url, "SELECT data FROM events WHERE kind='action_result'")
        lee_codes = [
            result
            for (d,) in data
            if (result := json.loads(d)["result"])["action"]["type"] == "send_qr"
            and result["action"]["contact"] == "lee"
            and result["ok"]
        ]
        assert len(lee_codes) == 1, lee_codes
        # The code Lee holds is the one the instruction watched and saw used.
        collected = [
            json.loads(d)["result"]
            for (d,) in data
            if json.loads(d)["result"]["action"]["type"] == "wait_in_place"
            and json.loads(d)["result"]["action"]["person"] == "lee"
        ]
        assert [c["ok"] for c in collected] == [True], collected
    finally:
        for replica in replicas:
            replica.stop()
