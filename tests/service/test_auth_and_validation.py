"""Every auth rule, and malformed input on every endpoint, against a real uvicorn server."""

from __future__ import annotations

from collections.abc import AsyncIterator
from pathlib import Path

import httpx
import pytest
import pytest_asyncio

from service.inprocess import running_service
from service.server import LEE, OPERATOR, ZHANG

# The tests whose every request is refused (or only reads) share one service (``refusing``),
# in the module's event loop and on one xdist worker: each of them that could leave something
# behind checks the instruction list is still empty. The tests that submit or change people
# start their own (``api``).
pytestmark = pytest.mark.shares_worker("refused")
IN_THE_SHARED_LOOP = pytest.mark.asyncio(loop_scope="module")

OP = {"Authorization": f"Bearer {OPERATOR}"}
AS_LEE = {"Authorization": f"Bearer {LEE}"}
AS_ZHANG = {"Authorization": f"Bearer {ZHANG}"}


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def refusing(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[httpx.AsyncClient]:
    data_dir = tmp_path_factory.mktemp("refused") / "data"
    async with running_service(data_dir, max_body_bytes=4096) as client:
        yield client


PROTECTED = [
    ("POST", "/v1/instructions"),
    ("GET", "/v1/instructions"),
    ("GET", "/v1/instructions/ins-x"),
    ("POST", "/v1/instructions/ins-x/cancel"),
    ("DELETE", "/v1/instructions/ins-x"),
    ("GET", "/v1/instructions/ins-x/events"),
    ("GET", "/v1/events"),
    ("GET", "/v1/memory"),
    ("PATCH", "/v1/people/lee"),
    ("PUT", "/v1/people/lee/items/stapler"),
    ("DELETE", "/v1/people/lee/items/stapler"),
    ("GET", "/v1/robot"),
    ("GET", "/v1/locker"),
    ("POST", "/v1/messages"),
    ("GET", "/v1/chats"),
    ("GET", "/v1/chats/dm/lee"),
    ("GET", "/metrics"),
]


@IN_THE_SHARED_LOOP
async def test_protected_endpoints_answer_401_with_www_authenticate(
    refusing: httpx.AsyncClient,
) -> None:
    for method, path in PROTECTED:
        for header in (None, "Bearer wrong-token-000000000000", "Basic abc", "Bearer"):
            headers = {"Authorization": header} if header else {}
            r = await refusing.request(method, path, headers=headers)
            assert r.status_code == 401, (method, path, header)
            assert r.headers["www-authenticate"].startswith("Bearer")
            assert r.json()["error"] == "unauthorized"


@IN_THE_SHARED_LOOP
async def test_health_needs_no_token(refusing: httpx.AsyncClient) -> None:
    assert (await refusing.get("/healthz")).json() == {"status": "ok"}
    assert (await refusing.get("/readyz")).json()["status"] == "ready"


async def test_a_person_submits_only_as_themselves(api: httpx.AsyncClient) -> None:
    body = {"requester": "zhang", "text": "bring me a stapler"}
    r = await api.post("/v1/instructions", json=body, headers=AS_LEE)
    assert r.status_code == 403 and "lee" in r.json()["message"]
    r = await api.post("/v1/instructions", json=body, headers=AS_ZHANG)
    assert r.status_code == 202


@pytest_asyncio.fixture
async def unhurried(tmp_path: Path) -> AsyncIterator[httpx.AsyncClient]:
    """A service at speed-up 1: an instruction it starts is still running minutes later, so
    a test can cancel it whatever the load (at the tests' speed-up 50 a stapler's whole
    fetch takes a few seconds of wall time, and a loaded machine let it end first)."""
    async with running_service(tmp_path / "data", speedup=1) as client:
        yield client


async def test_a_person_sees_only_their_own_instructions(unhurried: httpx.AsyncClient) -> None:
    api = unhurried
    r = await api.post(
        "/v1/instructions", json={"requester": "lee", "text": "a stapler"}, headers=AS_LEE
    )
    iid = r.json()["id"]
    # Someone else's id is answered exactly like an id that does not exist: nothing to probe.
    unknown = "ins-" + "0" * (len(iid) - 4)
    for path in ("/v1/instructions/{}", "/v1/instructions/{}/events"):
        theirs = await api.get(path.format(iid), headers=AS_ZHANG)
        missing = await api.get(path.format(unknown), headers=AS_ZHANG)
        assert theirs.status_code == missing.status_code == 404
        assert theirs.json() == {**missing.json(), "message": f"no instruction {iid!r}"}
    theirs = await api.post(f"/v1/instructions/{iid}/cancel", headers=AS_ZHANG)
    assert theirs.status_code == 404
    assert (await api.get(f"/v1/instructions/{iid}", headers=OP)).status_code == 200
    mine = (await api.get("/v1/instructions", headers=AS_ZHANG)).json()
    assert mine["items"] == []
    r = await api.get("/v1/instructions?requester=lee", headers=AS_ZHANG)
    assert r.status_code == 403
    assert [i["id"] for i in (await api.get("/v1/instructions", headers=OP)).json()["items"]] == [
        iid
    ]
    r = await api.delete(f"/v1/instructions/{iid}", headers=AS_LEE)
    assert r.status_code == 200 and r.json()["cancelled"] is True


async def test_operator_only_endpoints_refuse_people(api: httpx.AsyncClient) -> None:
    assert (
        await api.patch("/v1/people/lee", json={"available": False}, headers=AS_LEE)
    ).status_code == 403
    assert (await api.put("/v1/people/lee/items/stapler", headers=AS_LEE)).status_code == 403
    r = await api.patch("/v1/people/lee", json={"available": False}, headers=OP)
    assert r.status_code == 200 and r.json()["available"] == "unavailable"
    r = await api.put("/v1/people/lee/items/stapler", headers=OP)
    assert "stapler:lee" in r.json()["items"]
    r = await api.delete("/v1/people/lee/items/stapler", headers=OP)
    assert "stapler:lee" not in r.json()["items"]


async def test_messages_are_posted_only_as_oneself_and_chats_are_private(
    api: httpx.AsyncClient,
) -> None:
    r = await api.post("/v1/messages", json={"text": "hi", "sender": "zhang"}, headers=AS_LEE)
    assert r.status_code == 403
    r = await api.post(
        "/v1/messages", json={"text": "hello all", "group": "office_work"}, headers=AS_LEE
    )
    assert r.status_code == 202 and r.json()["chat"] == {"kind": "group", "id": "office_work"}
    assert (await api.get("/v1/chats/dm/lee", headers=AS_ZHANG)).status_code == 403
    assert (await api.get("/v1/chats/group/office_work", headers=AS_ZHANG)).status_code == 200
    r = await api.post("/v1/messages", json={"text": "hi"}, headers=OP)
    assert r.status_code == 422 and "sender" in r.json()["message"]


MALFORMED = [
    ("POST", "/v1/instructions", {"requester": "lee"}, "text"),
    ("POST", "/v1/instructions", {"requester": "lee", "text": ""}, "text"),
    ("POST", "/v1/instructions", {"requester": "lee", "text": "x", "extra": 1}, "extra"),
    ("POST", "/v1/instructions", {"requester": 5, "text": "x"}, "requester"),
    ("POST", "/v1/instructions", {"requester": "nobody", "text": "x"}, "nobody"),
    ("GET", "/v1/instructions?status=bogus", None, "status"),
    ("GET", "/v1/instructions?limit=0", None, "limit"),
    ("GET", "/v1/instructions?cursor=zzz", None, "cursor"),
    ("GET", "/v1/instructions/ins-missing", None, "ins-missing"),
    ("GET", "/v1/events?after=-1", None, "after"),
    ("PATCH", "/v1/people/nobody", {"available": True}, "nobody"),
    ("PATCH", "/v1/people/lee", {"available": "maybe"}, "available"),
    ("PATCH", "/v1/people/lee", {"location": "the moon"}, "moon"),
    ("PUT", "/v1/people/lee/items/unicorn", None, "unicorn"),
    ("POST", "/v1/messages", {"text": ""}, "text"),
    ("POST", "/v1/messages", {"text": "hi", "group": "no_such_group"}, "no_such_group"),
    ("POST", "/v1/messages", {"text": "hi", "files": ["file:nobody-x"]}, "nobody"),
    ("GET", "/v1/chats/room/lee", None, "kind"),
    ("GET", "/v1/chats/dm/nobody", None, "nobody"),
]


@IN_THE_SHARED_LOOP
async def test_malformed_input_gets_a_4xx_that_names_the_problem(
    refusing: httpx.AsyncClient,
) -> None:
    for method, path, body, named in MALFORMED:
        headers = OP if "messages" not in path else AS_LEE
        r = await refusing.request(method, path, json=body, headers=headers)
        assert 400 <= r.status_code < 500, (path, r.text)
        assert named in r.text, (path, r.text)


@IN_THE_SHARED_LOOP
async def test_not_json_and_oversized_bodies(refusing: httpx.AsyncClient) -> None:
    r = await refusing.post(
        "/v1/instructions",
        content=b"{not json",
        headers={**AS_LEE, "content-type": "application/json"},
    )
    assert r.status_code == 422 and r.json()["error"] == "invalid_request"
    big = {"requester": "lee", "text": "x" * 5000}
    r = await refusing.post("/v1/instructions", json=big, headers=AS_LEE)
    assert r.status_code == 413 and "4096" in r.json()["message"]
    listed = (await refusing.get("/v1/instructions", headers=OP)).json()["items"]
    assert listed == []  # nothing malformed reached the loop


@IN_THE_SHARED_LOOP
async def test_a_streamed_body_over_the_limit_gets_413_not_400(refusing: httpx.AsyncClient) -> None:
    """Chunked, with no Content-Length: the limit counts what arrives, and the answer is the
    same 413 as for a declared size (the framework's own "400 error parsing the body" was)."""

    async def chunks() -> AsyncIterator[bytes]:
        yield b'{"requester": "lee", "text": "'
        for _ in range(5):
            yield b"x" * 1000
        yield b'"}'

    r = await refusing.post(
        "/v1/instructions", content=chunks(), headers={**AS_LEE, "content-type": "application/json"}
    )
    assert r.status_code == 413 and "4096" in r.json()["message"]
    listed = (await refusing.get("/v1/instructions", headers=OP)).json()["items"]
    assert listed == []


@IN_THE_SHARED_LOOP
async def test_a_deeply_nested_body_gets_a_json_4xx(refusing: httpx.AsyncClient) -> None:
    deep = b"[" * 1500 + b"]" * 1500
    r = await refusing.post(
        "/v1/instructions", content=deep, headers={**AS_LEE, "content-type": "application/json"}
    )
    assert 400 <= r.status_code < 500 and r.headers["content-type"] == "application/json"
    assert r.json()["error"]
