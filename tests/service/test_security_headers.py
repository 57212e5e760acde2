"""Every answer of the service carries the headers that keep the dashboard to itself: a
content security policy that forbids framing, nosniff, and no referrer (issue 24)."""

from __future__ import annotations

from pathlib import Path

from service.test_dashboard import serve


async def test_every_answer_carries_the_security_headers(tmp_path: Path) -> None:
    async with serve(tmp_path, max_body_bytes=1024) as client:
        answers = {
            "page": await client.get("/", headers={"Authorization": ""}),
            "script": await client.get("/js/app.js", headers={"Authorization": ""}),
            "docs": await client.get("/docs", headers={"Authorization": ""}),
            "json": await client.get("/v1/instructions"),
            "not found": await client.get("/v1/instructions/ins-nothing"),
            "unauthorized": await client.get("/v1/robot", headers={"Authorization": ""}),
            "too large": await client.post("/v1/instructions", content=b"x" * 2048),
        }
    statuses = {name: r.status_code for name, r in answers.items()}
    assert statuses == {
        "page": 200,
        "script": 200,
        "docs": 200,
        "json": 200,
        "not found": 404,
        "unauthorized": 401,
        "too large": 413,
    }
    for name, answer in answers.items():
        policy = answer.headers.get("content-security-policy", "")
        directives = dict(d.strip().partition(" ")[::2] for d in policy.split(";"))
        assert directives.get("frame-ancestors") == "'none'", name
        assert directives.get("default-src") == "'self'", name
        assert "'unsafe-inline'" not in policy and "'unsafe-eval'" not in policy, name
        assert answer.headers.get("x-content-type-options") == "nosniff", name
        assert answer.headers.get("referrer-policy") == "no-referrer", name
        assert answer.headers.get("x-frame-options") == "DENY", name
