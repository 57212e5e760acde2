"""Numbers beyond what the journal stores, and text or names no person writes, get a one-line
422 over real HTTP (not a 500 with a traceback)."""

from __future__ import annotations

import base64
from collections.abc import AsyncIterator

import httpx
import pytest
import pytest_asyncio

from service.inprocess import running_service
from service.server import LEE, OPERATOR

# One service for the module: every request here is refused and none may leave anything
# behind (each test checks the instruction list stays empty), so the tests share it instead
# of starting one each (14 starts), on one xdist worker.
pytestmark = [pytest.mark.asyncio(loop_scope="module"), pytest.mark.shares_worker("refusals")]

OP = {"Authorization": f"Bearer {OPERATOR}"}
AS_LEE = {"Authorization": f"Bearer {LEE}"}
TOO_BIG = [2**63, 2**64, 10**30]


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def api(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[httpx.AsyncClient]:
    data_dir = tmp_path_factory.mktemp("refusals") / "data"
    async with running_service(data_dir, max_body_bytes=4096) as client:
        yield client


def _cursor(seq: int) -> str:
    return base64.urlsafe_b64encode(f"s{seq}".encode()).decode().rstrip("=")


@pytest.mark.parametrize("number", TOO_BIG)
async def test_sequence_numbers_beyond_64_bits_are_422(api: httpx.AsyncClient, number: int) -> None:
    requests = [
        ("/v1/events", {"after": number}, {}),
        ("/v1/instructions/ins-x/events", {"after": number}, {}),
        ("/v1/chats/dm/lee", {"after": number}, {}),
        ("/v1/instructions", {"cursor": _cursor(number)}, {}),
    ]
    if len(str(number)) <= 20:  # the header's own length cap answers longer ones
        requests += [
            ("/v1/events", {}, {"Last-Event-ID": str(number)}),
            ("/v1/instructions/ins-x/events", {}, {"Last-Event-ID": str(number)}),
        ]
    for path, params, headers in requests:
        r = await api.get(path, params=params, headers={**OP, **headers})
        assert r.status_code == 422, (path, params, headers, r.text)
        assert r.json()["error"] and "Traceback" not in r.text


async def test_the_largest_sequence_number_is_accepted(api: httpx.AsyncClient) -> None:
    r = await api.get("/v1/chats/dm/lee", params={"after": 2**63 - 1}, headers=OP)
    assert (r.status_code, r.json()) == (200, [])
    r = await api.get("/v1/instructions", params={"cursor": _cursor(2**63 - 1)}, headers=OP)
    assert r.status_code == 200


@pytest.mark.parametrize("text", ["\x00", "\x00\x00\x00", " \x00 \n", "hello\x00world", "\u200b"])
async def test_text_without_visible_characters_or_with_nul_is_422(
    api: httpx.AsyncClient, text: str
) -> None:
    r = await api.post("/v1/instructions", json={"requester": "lee", "text": text}, headers=AS_LEE)
    assert r.status_code == 422, r.text
    assert "text" in r.json()["message"]
    r = await api.post("/v1/messages", json={"text": text}, headers=AS_LEE)
    assert r.status_code == 422, r.text
    assert (await api.get("/v1/instructions", headers=OP)).json()["items"] == []


@pytest.mark.parametrize(
    "name", ["lee\x00", "l\nee", "lee\r\nX-Forged: 1", "\x1b[31mlee", "le\x07e"]
)
async def test_names_with_control_characters_are_422(api: httpx.AsyncClient, name: str) -> None:
    r = await api.post(
        "/v1/instructions", json={"requester": name, "text": "a stapler"}, headers=OP
    )
    assert r.status_code == 422, r.text
    assert "requester" in r.json()["message"]
    r = await api.post("/v1/messages", json={"text": "hi", "sender": name}, headers=OP)
    assert r.status_code == 422, r.text
    r = await api.post("/v1/messages", json={"text": "hi", "group": name}, headers=AS_LEE)
    assert r.status_code == 422, r.text
    assert (await api.get("/v1/instructions", headers=OP)).json()["items"] == []
