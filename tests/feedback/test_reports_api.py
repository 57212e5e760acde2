"""The survey and the usage report through the real service (uvicorn on 127.0.0.1)."""

from __future__ import annotations

from collections.abc import AsyncIterator
from pathlib import Path
from typing import Any

import httpx
import pytest
import pytest_asyncio

from helpers.eventually import eventually
from service.inprocess import running_service
from service.server import LEE, OPERATOR, ZHANG

AUTH_LEE = {"Authorization": f"Bearer {LEE}"}
AUTH_ZHANG = {"Authorization": f"Bearer {ZHANG}"}
AUTH_OP = {"Authorization": f"Bearer {OPERATOR}"}


# The tests that are only refused share one service (``unused_api``), in the module's event
# loop and on one xdist worker.
pytestmark = pytest.mark.shares_worker("reports")
IN_THE_SHARED_LOOP = pytest.mark.asyncio(loop_scope="module")


@pytest.fixture
async def api(tmp_path: Path) -> AsyncIterator[httpx.AsyncClient]:
    async with running_service(
        tmp_path / "data", speedup=200, reasoner_builder="service.stapler_reasoner:build_factory"
    ) as client:
        yield client


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def unused_api(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[httpx.AsyncClient]:
    """A service no one has asked anything yet, for the tests that are only refused: they
    share it (a service per test cost about 0.1 CPU-s and 0.3-0.5 s of wall time)."""
    data_dir = tmp_path_factory.mktemp("reports") / "data"
    async with running_service(
        data_dir, speedup=200, reasoner_builder="service.stapler_reasoner:build_factory"
    ) as client:
        yield client


async def _until(client: httpx.AsyncClient, url: str, ok: int = 200) -> httpx.Response:
    return await eventually(
        lambda: client.get(url, headers=AUTH_OP),
        until=lambda r: r.status_code == ok,
        what=f"{url} to answer {ok}",
    )


async def test_survey_over_the_builtin_messenger_and_the_report(api: httpx.AsyncClient) -> None:
    r = await api.post(
        "/v1/instructions",
        json={"requester": "lee", "text": "Bring me a stapler"},
        headers=AUTH_LEE,
    )
    assert r.status_code == 202, r.text
    iid = r.json()["id"]
    survey = (await _until(api, f"/v1/surveys/{iid}")).json()["survey"]
    assert survey["state"] == "open" and survey["person"] == "lee"
    # the survey is recorded open before its question reaches Lee's chat: wait for the message
    await eventually(
        lambda: api.get("/v1/chats/dm/lee", headers=AUTH_LEE),
        until=lambda r: any("A short survey" in m["text"] for m in r.json()),
        what="the survey's question in Lee's chat",
    )

    # Lee answers through the built-in messenger; it is a survey reply, not an instruction.
    r = await api.post("/v1/messages", json={"text": "y/n/?/y, quick and easy"}, headers=AUTH_LEE)
    assert r.status_code == 202

    async def survey() -> dict[str, Any]:
        body: dict[str, Any] = (await api.get(f"/v1/surveys/{iid}", headers=AUTH_LEE)).json()
        return body

    body = await eventually(
        survey, until=lambda b: b["survey"]["state"] == "complete", what="the survey's answers"
    )
    assert body["survey"]["answers"] == {
        "success": "yes",
        "walking": "no",
        "satisfied": "unsure",
        "productivity": "yes",
    }
    assert body["survey"]["comment"] == "quick and easy"
    assert [r["text"] for r in body["replies"]] == ["y/n/?/y, quick and easy"]
    listed = (await api.get("/v1/instructions", headers=AUTH_OP)).json()["items"]
    assert [i["id"] for i in listed] == [iid]

    report = (await api.get("/v1/reports/usage", headers=AUTH_OP)).json()
    assert report["instructions"]["total"] == 1
    assert report["instructions"]["by_outcome"]["done"] == 1
    assert report["instructions"]["by_kind"] == {"delivery": {"done": 1}}
    assert report["surveys"]["complete"] == 1
    walking = report["surveys"]["questions"][1]
    assert walking["id"] == "walking" and walking["answers"]["no"] == {"count": 1, "share": 1.0}
    assert report["walking"]["method"] == {"map": 1}
    assert report["walking"]["by_person"]["lee"]["saved_m"] > 0

    # A person sees only their own figures; Zhang has none.
    mine = (await api.get("/v1/reports/usage", headers=AUTH_ZHANG)).json()
    assert mine["instructions"]["total"] == 0 and mine["period"]["requester"] == "zhang"
    assert (await api.get("/v1/reports/usage?person=lee", headers=AUTH_ZHANG)).status_code == 403
    assert (await api.get(f"/v1/surveys/{iid}", headers=AUTH_ZHANG)).status_code == 404

    # The period: ended before 'from' counts nothing; a bare 'to' date includes that day.
    empty = (await api.get("/v1/reports/usage?from=2999-01-01", headers=AUTH_OP)).json()
    assert empty["instructions"]["total"] == 0
    assert empty["surveys"]["response_rate"] is None
    dated = await api.get("/v1/reports/usage?from=2000-01-01&to=2999-12-31", headers=AUTH_OP)
    assert dated.json()["instructions"]["total"] == 1

    md = await api.get("/v1/reports/usage.md", headers=AUTH_OP)
    assert md.headers["content-type"].startswith("text/markdown")
    assert "| Did it save you walking? | 0 (0%) | 1 (100%) | 0 (0%) | 0 |" in md.text
    for name in ("outcomes", "survey", "walking"):
        png = await api.get(f"/v1/reports/usage/charts/{name}.png", headers=AUTH_OP)
        assert png.headers["content-type"] == "image/png"
        assert png.content.startswith(b"\x89PNG\r\n\x1a\n") and len(png.content) > 5000


@pytest.mark.parametrize(
    ("url", "status"),
    [
        ("/v1/reports/usage?from=yesterday", 422),
        ("/v1/reports/usage?from=2025-02-01&to=2025-01-01", 422),
        ("/v1/reports/usage?person=nobody", 422),
        # float() reads these, but they are no moments: once taken, they made empty reports
        ("/v1/reports/usage?from=nan", 422),
        ("/v1/reports/usage?from=1e20", 422),
        ("/v1/reports/usage?to=inf", 422),
        ("/v1/reports/usage?from=-1", 422),
        ("/v1/reports/usage/charts/pie.png", 404),
        ("/v1/surveys/ins-unknown", 404),
    ],
)
@IN_THE_SHARED_LOOP
async def test_bad_requests_say_what_is_wrong(
    unused_api: httpx.AsyncClient, url: str, status: int
) -> None:
    r = await unused_api.get(url, headers=AUTH_OP)
    assert r.status_code == status, r.text
    assert r.json()["message"] and "\n" not in r.json()["message"]


@IN_THE_SHARED_LOOP
async def test_reports_need_a_token(unused_api: httpx.AsyncClient) -> None:
    r = await unused_api.get("/v1/reports/usage")
    assert r.status_code == 401
    assert "www-authenticate" in r.headers
