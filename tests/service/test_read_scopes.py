"""What a person token may read of others' activity (memory updates, metrics, people), over
HTTP against a real uvicorn server with simulated colleagues and the embedded reasoner."""

from __future__ import annotations

import json
from collections.abc import AsyncIterator

import httpx
import pytest
import pytest_asyncio

from helpers.instructions import ended
from service.inprocess import running_service
from service.server import LEE, OPERATOR, ZHANG

# The tests read what one instruction of Zhang's left (and the operator's correction of one
# test adds nothing the others look at): they share one service and that one instruction, in
# the module's event loop and on one xdist worker, instead of a service and a run each.
pytestmark = [pytest.mark.asyncio(loop_scope="module"), pytest.mark.shares_worker("scopes")]

OP = {"Authorization": f"Bearer {OPERATOR}"}
AS_LEE = {"Authorization": f"Bearer {LEE}"}
AS_ZHANG = {"Authorization": f"Bearer {ZHANG}"}


async def _memory_updates(api: httpx.AsyncClient, headers: dict[str, str]) -> list[dict]:  # type: ignore[type-arg]
    r = await api.get("/v1/memory", headers=headers)
    assert r.status_code == 200
    updates: list[dict] = r.json()["updates"]  # type: ignore[type-arg]
    return updates


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def api(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[httpx.AsyncClient]:
    data_dir = tmp_path_factory.mktemp("scopes") / "data"
    # speed-up 200: the tests read what the stapler instruction left once it ended
    async with running_service(data_dir, max_body_bytes=4096, speedup=200) as client:
        yield client


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def zhang_iid(api: httpx.AsyncClient) -> str:
    """Zhang asks for a stapler with their own token; the id once the instruction ended."""
    r = await api.post(
        "/v1/instructions",
        json={"requester": "zhang", "text": "bring me a stapler"},
        headers=AS_ZHANG,
    )
    iid: str = r.json()["id"]
    await ended(api, iid, OP)
    return iid


async def test_a_person_reads_only_their_own_instructions_memory_updates(
    api: httpx.AsyncClient, zhang_iid: str
) -> None:
    await api.patch("/v1/people/wang", json={"available": False}, headers=OP)

    everything = await _memory_updates(api, OP)
    by_zhang = [u for u in everything if u["instruction_id"] == zhang_iid]
    assert by_zhang, "the instruction should have taught memory something"
    assert any(u["instruction_id"] is None for u in everything)  # the operator's correction

    assert await _memory_updates(api, AS_LEE) == []  # neither Zhang's nor the operator's
    assert await _memory_updates(api, AS_ZHANG) == by_zhang

    lee_sees = (await api.get("/v1/memory", headers=AS_LEE)).text
    assert zhang_iid not in lee_sees
    for update in by_zhang:
        evidence = update["update"].get("evidence")
        if evidence:
            assert json.dumps(evidence)[1:-1] not in lee_sees


async def test_metrics_are_for_the_operator(api: httpx.AsyncClient) -> None:
    assert (await api.get("/metrics", headers=AS_LEE)).status_code == 403
    r = await api.get("/metrics", headers=OP)
    assert r.status_code == 200 and "assistantx_instructions" in r.text


async def test_a_person_record_carries_no_instruction_ids_or_excerpts(
    api: httpx.AsyncClient, zhang_iid: str
) -> None:
    touched = {
        u["update"].get("person") for u in await _memory_updates(api, OP) if u["instruction_id"]
    } - {None}
    assert touched
    for person in touched:
        body = (await api.get(f"/v1/people/{person}", headers=AS_LEE)).json()
        assert set(body) == {
            "id",
            "name",
            "available",
            "observed_at",
            "location",
            "items",
            "groups",
        }
        assert zhang_iid not in json.dumps(body)
