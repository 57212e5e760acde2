"""The real server as a subprocess: an L2 instruction over REST, its SSE stream, the built-in
messenger's transcripts, and a kill -9 mid-instruction followed by a restart that finishes
the instruction once, with no message or QR code sent twice."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import httpx
import pytest

from helpers.instructions import submit_stapler
from service.server import LEE, OPERATOR, free_port, serve, sse

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow

AUTH_LEE = {"Authorization": f"Bearer {LEE}"}
AUTH_OP = {"Authorization": f"Bearer {OPERATOR}"}


def _transcript(client: httpx.Client, person: str) -> list[dict[str, object]]:
    r = client.get(f"/v1/chats/dm/{person}", headers=AUTH_OP)
    assert r.status_code == 200
    return list(r.json())


def test_l2_instruction_over_rest_with_sse_and_transcripts(tmp_path: Path) -> None:
    port = free_port()
    server = serve(tmp_path / "data", port, ASSISTANTX_SIM_UNAVAILABLE="wang")
    try:
        with httpx.Client(base_url=server.url, timeout=10) as client:
            iid = submit_stapler(client, AUTH_LEE)
            kinds = [kind for _, kind, _ in sse(client, f"/v1/instructions/{iid}/events", LEE)]
            assert kinds[0] == "instruction_started" and kinds[-1] == "instruction_ended"
            body = client.get(f"/v1/instructions/{iid}", headers=AUTH_LEE).json()
            assert body["status"] == "done" and body["outcome"] == "done"
            asked = [
                s["results"][0]["action"]["contact"]
                for s in body["trace"]["steps"]
                if s["results"] and s["results"][0]["action"]["type"] == "inquire"
            ]
            assert asked == ["wang", "zhang"]  # wang (first known owner) never answered
            memory = client.get("/v1/people/wang", headers=AUTH_LEE).json()
            assert memory["available"] == "unavailable"
            zhang = _transcript(client, "zhang")
            assert [m["direction"] for m in zhang][:2] == ["out", "in"]
            lee = _transcript(client, "lee")
            told = [str(m["text"]) for m in lee if not str(m["text"]).startswith("A short survey")]
            assert told[-1].startswith("[done]")  # then the survey (assistantx.feedback)
    finally:
        server.stop()


def test_kill_mid_instruction_then_restart_finishes_once(tmp_path: Path) -> None:
    port = free_port()
    server = serve(tmp_path / "data", port, ASSISTANTX_SIM_UNAVAILABLE="wang")
    last = 0
    try:
        with httpx.Client(base_url=server.url, timeout=10) as client:
            iid = submit_stapler(client, AUTH_LEE)
            for event_id, kind, data in sse(client, f"/v1/instructions/{iid}/events", LEE):
                last = event_id
                result = data["data"].get("result", {})  # type: ignore[union-attr]
                if kind == "action_result" and result["action"]["type"] == "send_qr":
                    break  # zhang holds a code and the robot waits at her desk: kill now
    finally:
        server.kill()

    server = serve(tmp_path / "data", port, ASSISTANTX_SIM_UNAVAILABLE="wang")
    try:
        with httpx.Client(base_url=server.url, timeout=10) as client:
            ready = client.get("/readyz").json()
            assert iid in ready["resumed"]
            rest = list(sse(client, f"/v1/instructions/{iid}/events", LEE, last_id=last))
            assert rest and rest[-1][1] == "instruction_ended"
            assert all(event_id > last for event_id, _, _ in rest)
            body = client.get(f"/v1/instructions/{iid}", headers=AUTH_LEE).json()
            assert body["status"] == "done", body["summary"]
            messages = _transcript(client, "zhang") + _transcript(client, "lee")
            outbound = Counter(
                (m["chat"]["id"], m["text"])  # type: ignore[index]
                for m in messages
                if m["direction"] == "out"
            )
            assert outbound and max(outbound.values()) == 1, outbound
            qr = [m for m in messages if m["attachments"] and m["direction"] == "out"]
            codes = [m for m in qr if "one-time code" in str(m["text"])]
            assert sorted(m["chat"]["id"] for m in codes) == ["lee", "zhang"]  # type: ignore[index]
            done = [m for m in messages if str(m["text"]).startswith("[done]")]
            assert len(done) == 1
            ended = client.get(f"/v1/instructions/{iid}/events", headers=AUTH_OP).text
            assert ended.count("event: instruction_ended") == 1
    finally:
        server.stop()


def test_a_cancelled_code_stays_refused_after_kill_9(tmp_path: Path) -> None:
    """Cancel after the lender's deposit code went out, kill -9, restart: the code (which the
    lender may still hold) is refused as revoked, and the lender is not sent another."""
    port = free_port()
    slow = {"ASSISTANTX_ROBOT": "sim", "ASSISTANTX_SIM_HANDOVER_DELAY_S": "3600"}
    server = serve(tmp_path / "data", port, **slow)
    code_id = ""
    try:
        with httpx.Client(base_url=server.url, timeout=10) as client:
            iid = submit_stapler(client, AUTH_LEE)
            for _, kind, data in sse(client, f"/v1/instructions/{iid}/events", LEE):
                result = data["data"].get("result", {})  # type: ignore[union-attr]
                if kind == "action_result" and result["action"]["type"] == "send_qr":
                    code_id = result["data"]["code_id"]
                    break
            assert client.post(f"/v1/instructions/{iid}/cancel", headers=AUTH_LEE).is_success
            list(sse(client, f"/v1/instructions/{iid}/events", LEE))  # ends once it ended
            status = client.get(f"/v1/instructions/{iid}", headers=AUTH_LEE).json()["status"]
            assert status == "cancelled"
    finally:
        server.kill()

    server = serve(tmp_path / "data", port, **slow)
    try:
        with httpx.Client(base_url=server.url, timeout=10) as client:
            scan = client.post("/v1/locker/scan", json={"code_id": code_id}, headers=AUTH_OP)
            assert scan.status_code == 200, scan.text
            assert (scan.json()["kind"], scan.json()["reason"]) == ("code_rejected", "revoked")
            codes = [m for m in _transcript(client, "wang") if m["attachments"]]
            assert len(codes) == 1
    finally:
        server.stop()
