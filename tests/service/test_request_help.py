"""What a newcomer sees of the REST API before reading any code: /openapi.json (and so /docs)
shows an instruction's fields with an example, and a wrong request body gets one line that
says what to send instead, over real HTTP."""

from __future__ import annotations

from collections.abc import AsyncIterator

import httpx
import pytest
import pytest_asyncio

from service.inprocess import running_service
from service.server import LEE, OPERATOR

# Every request here only reads or is refused: the tests share one service (the module's
# event loop, one xdist worker) instead of starting one each.
pytestmark = [pytest.mark.asyncio(loop_scope="module"), pytest.mark.shares_worker("help")]

AS_LEE = {"Authorization": f"Bearer {LEE}"}
EXAMPLE = '{"requester": "lee", "text": "Bring me a stapler"}'


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def api(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[httpx.AsyncClient]:
    data_dir = tmp_path_factory.mktemp("help") / "data"
    async with running_service(data_dir, max_body_bytes=4096) as client:
        yield client


async def test_openapi_shows_the_instruction_fields_and_an_example(
    api: httpx.AsyncClient,
) -> None:
    schema = (await api.get("/openapi.json")).json()
    body = schema["components"]["schemas"]["InstructionIn"]
    assert set(body["required"]) == {"requester", "text"}
    assert "person" in body["properties"]["requester"]["description"]
    assert "words" in body["properties"]["text"]["description"]
    assert body["examples"] == [{"requester": "lee", "text": "Bring me a stapler"}]


async def test_bad_json_says_it_is_not_json_and_shows_a_body_to_send(
    api: httpx.AsyncClient,
) -> None:
    r = await api.post(
        "/v1/instructions",
        content=b'{"requester": "lee", "text": bring me a stapler}',
        headers={**AS_LEE, "Content-Type": "application/json"},
    )
    assert r.status_code == 422, r.text
    message = r.json()["message"]
    assert message.startswith("the body is not valid JSON"), message
    assert "decode error" not in message
    assert EXAMPLE in message and "\n" not in message


async def test_a_body_without_content_type_is_told_to_send_json(api: httpx.AsyncClient) -> None:
    r = await api.post(
        "/v1/instructions",
        content=b'{"requester": "lee", "text": "Bring me a stapler"}',
        headers={**AS_LEE, "Content-Type": ""},
    )
    assert r.status_code == 422, r.text
    message = r.json()["message"]
    assert "Content-Type: application/json" in message, message
    assert "valid dictionary" not in message
    assert EXAMPLE in message


async def test_blank_text_is_called_blank(api: httpx.AsyncClient) -> None:
    for text in ["", "   ", "\n\t "]:
        r = await api.post(
            "/v1/instructions", json={"requester": "lee", "text": text}, headers=AS_LEE
        )
        assert r.status_code == 422, r.text
        assert r.json()["message"] == "text must not be blank"


async def test_a_missing_field_names_it_and_shows_a_body_to_send(api: httpx.AsyncClient) -> None:
    r = await api.post("/v1/instructions", json={"text": "Bring me a stapler"}, headers=AS_LEE)
    assert r.status_code == 422, r.text
    assert r.json()["message"] == f"requester is missing: send a JSON object such as {EXAMPLE}"


async def test_me_names_the_tokens_person_or_the_operator(api: httpx.AsyncClient) -> None:
    me = await api.get("/v1/me", headers=AS_LEE)
    assert me.json() == {"person": "lee", "name": "Lee Ming", "operator": False}
    operator = await api.get("/v1/me", headers={"Authorization": f"Bearer {OPERATOR}"})
    assert operator.json() == {"person": None, "name": None, "operator": True}
    assert (await api.get("/v1/me", headers={"Authorization": "Bearer nope"})).status_code == 401
