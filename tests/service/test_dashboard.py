"""The dashboard's own routes on the real app over a real uvicorn server: the page, the map and
its PNG (checked against the map file through the documented world→pixel transform), evaluation
results, and the locker codes with the operator's simulated scan."""

from __future__ import annotations

import contextlib
import io
import json
import os
from collections.abc import AsyncIterator
from pathlib import Path

import httpx
import numpy as np
import pytest
import pytest_asyncio

from assistantx.adapters.robot.navigator import DEFAULT_MAP
from assistantx.core.office import load_office
from assistantx.core.settings import Settings
from assistantx.nav.anchors import load_anchors
from assistantx.nav.occupancy_map import load_map
from assistantx.service.app import create_app
from assistantx.service.dashboard import occupancy_grey
from helpers.eventually import eventually
from helpers.servers import serving_app

TOKEN = "operator-token-for-dashboard-tests"
LEE_TOKEN = "lee-token-for-dashboard-tests-01"

pytestmark = [pytest.mark.asyncio(loop_scope="module"), pytest.mark.shares_worker("dashboard")]


@contextlib.asynccontextmanager
async def serve(tmp_path: Path, **overrides: object) -> AsyncIterator[httpx.AsyncClient]:
    values: dict[str, object] = {
        "data_dir": tmp_path / "data",
        "results_dir": tmp_path / "results",
        "operator_token": TOKEN,
        "tokens": json.dumps({LEE_TOKEN: "lee"}),
        "people": "human",
        "speedup": 200,
        "reasoner_builder": "service.stapler_reasoner:build_factory",
        "robot_localize": False,  # kinematic paths: these tests are about the page
    }
    settings = Settings(**{**values, **overrides})  # type: ignore[arg-type]
    headers = {"Authorization": f"Bearer {TOKEN}"}
    async with serving_app(create_app(settings), headers=headers) as client:
        yield client


# The tests that only read (the page, the map, a results folder with no run) share one server,
# and the five paths outside a run's files another; a server per test cost about 0.1 CPU-s and
# 0.3-0.5 s of wall time to start and stop. The tests that write (runs, codes) start their own.
@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def client(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[httpx.AsyncClient]:
    async with serve(tmp_path_factory.mktemp("dashboard")) as c:
        yield c


async def test_the_page_and_its_scripts_are_public(client: httpx.AsyncClient) -> None:
    page = await client.get("/", headers={"Authorization": ""})
    assert page.status_code == 200
    assert page.headers["content-type"].startswith("text/html")
    assert "<title>AssistantX dashboard</title>" in page.text
    assert '<script type="module" src="/js/app.js">' in page.text
    for asset in ("/js/app.js", "/styles.css", "/js/map.js", "/js/stream.js"):
        response = await client.get(asset, headers={"Authorization": ""})
        assert response.status_code == 200, asset
    assert (await client.get("/../service/dashboard.py")).status_code == 404


async def test_dashboard_routes_need_a_token_and_the_locker_the_operator(
    client: httpx.AsyncClient,
) -> None:
    for path in ("/v1/map", "/v1/map.png", "/v1/evaluation/latest", "/v1/locker/codes"):
        response = await client.get(path, headers={"Authorization": "Bearer wrong-token-123456"})
        assert response.status_code == 401, path
    lee = {"Authorization": f"Bearer {LEE_TOKEN}"}
    assert (await client.get("/v1/map", headers=lee)).status_code == 200
    assert (await client.get("/v1/locker/codes", headers=lee)).status_code == 403
    scan = await client.post("/v1/locker/scan", json={"code_id": "x"}, headers=lee)
    assert scan.status_code == 403


async def test_map_metadata_describes_the_map_file_and_names_every_place(
    client: httpx.AsyncClient,
) -> None:
    info = (await client.get("/v1/map")).json()
    grid = load_map(DEFAULT_MAP)
    assert info["image"] == "/v1/map.png"
    assert info["resolution"] == grid.resolution
    assert info["origin"] == [grid.origin_x, grid.origin_y]
    assert (info["width"], info["height"]) == (grid.width, grid.height)
    office = load_office()
    for location in office.locations:
        anchor = info["anchors"][location.id]
        assert anchor["name"] == location.name
        assert anchor["kind"] == location.kind
    file_anchors = load_anchors(DEFAULT_MAP.with_name("office.anchors.yaml"))
    assert info["anchors"]["print_room"]["x"] == file_anchors["print_room"].x
    assert info["anchors"]["print_room"]["yaw"] == file_anchors["print_room"].yaw


async def test_map_png_has_one_pixel_per_cell_with_the_top_row_last(
    client: httpx.AsyncClient,
) -> None:
    info = (await client.get("/v1/map")).json()
    response = await client.get("/v1/map.png")
    assert response.headers["content-type"] == "image/png"
    from matplotlib.image import imread  # here, not at collection: a CPU-second a worker

    image = imread(io.BytesIO(response.content), format="png")
    assert image.shape[:2] == (info["height"], info["width"])
    grey = np.rint(image[:, :, 0] * 255).astype(int)
    grid = load_map(DEFAULT_MAP)
    expected = occupancy_grey(grid.data)

    def pixel(x: float, y: float) -> tuple[int, int]:  # the transform the page uses
        px = (x - info["origin"][0]) / info["resolution"]
        py = info["height"] - (y - info["origin"][1]) / info["resolution"]
        return int(px), int(py)

    # Every anchor stands on free floor, as the page draws it.
    for anchor in info["anchors"].values():
        px, py = pixel(anchor["x"], anchor["y"])
        assert grey[py, px] == 254
    # And a whole-image comparison: the PNG is the grid flipped (row 0 of the grid = bottom).
    assert np.array_equal(grey, np.flipud(expected))
    assert (grey == 0).any()  # walls are there, dark


def _write_run(results: Path, name: str, summary: object, mtime: float) -> Path:
    run = results / name
    run.mkdir(parents=True)
    (run / "summary.json").write_text(json.dumps(summary), encoding="utf-8")
    (run / "summary.md").write_text(f"# {name}\n\n| level | SR |\n|---|---|\n| L1 | 0.9 |\n")
    (run / "sr_by_level.png").write_bytes(b"\x89PNG fake chart of " + name.encode())
    os.utime(run / "summary.json", (mtime, mtime))
    return run


async def test_evaluation_latest_is_the_newest_summary(tmp_path: Path) -> None:
    results = tmp_path / "results"
    _write_run(results, "2024-old", {"levels": {"L1": {"SR": 0.5}}}, mtime=1_000)
    _write_run(results, "2024-new", {"levels": {"L1": {"SR": 0.9}}}, mtime=2_000)
    (results / "not-a-run").mkdir()
    async with serve(tmp_path) as client:
        latest = (await client.get("/v1/evaluation/latest")).json()
        assert latest["run"] == "2024-new"
        assert latest["summary"] == {"levels": {"L1": {"SR": 0.9}}}
        assert latest["markdown"].startswith("# 2024-new")
        assert latest["charts"] == ["/v1/evaluation/runs/2024-new/sr_by_level.png"]
        chart = await client.get(latest["charts"][0])
        assert chart.status_code == 200
        assert chart.headers["content-type"] == "image/png"
        assert chart.content == b"\x89PNG fake chart of 2024-new"
        old = await client.get("/v1/evaluation/runs/2024-old/summary.json")
        assert old.json() == {"levels": {"L1": {"SR": 0.5}}}


@pytest.mark.parametrize(
    "path",
    [
        "/v1/evaluation/runs/2024-new/..%2F..%2Fsecret.png",
        "/v1/evaluation/runs/..%2F/summary.json",
        "/v1/evaluation/runs/2024-new/.hidden.png",
        "/v1/evaluation/runs/2024-new/notes.txt",
        "/v1/evaluation/runs/2024-new/missing.png",
    ],
)
async def test_evaluation_files_are_plain_names_inside_a_run(
    run_with_neighbours: httpx.AsyncClient, path: str
) -> None:
    response = await run_with_neighbours.get(path)
    assert response.status_code == 404
    assert b"secret" not in response.content


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def run_with_neighbours(
    tmp_path_factory: pytest.TempPathFactory,
) -> AsyncIterator[httpx.AsyncClient]:
    """A server whose results hold one run, a file beside the results and one in the run that
    is not a chart or summary (only read: shared by the paths above)."""
    root = tmp_path_factory.mktemp("evaluation-files")
    results = root / "results"
    _write_run(results, "2024-new", {}, mtime=1_000)
    (root / "secret.png").write_bytes(b"secret")
    (results / "2024-new" / "notes.txt").write_text("not served")
    async with serve(root) as client:
        yield client


async def test_no_evaluation_yet_says_where_it_looked(client: httpx.AsyncClient) -> None:
    response = await client.get("/v1/evaluation/latest")
    assert response.status_code == 404
    assert "results" in response.json()["message"]


async def test_a_half_written_summary_is_a_clear_503(tmp_path: Path) -> None:
    results = tmp_path / "results"
    run = _write_run(results, "run-1", {}, mtime=1_000)
    (run / "summary.json").write_text('{"levels": ', encoding="utf-8")
    async with serve(tmp_path) as client:
        response = await client.get("/v1/evaluation/latest")
        assert response.status_code == 503
        assert "run-1" in response.json()["message"]
        assert "summary.json" in response.json()["message"]


async def _wait_for(
    client: httpx.AsyncClient, path: str, ready: object, timeout_s: float = 20
) -> object:
    async def body() -> object:
        return (await client.get(path)).json()

    return await eventually(
        body, until=ready, what=f"{path} to be ready", timeout_s=timeout_s, interval_s=0.05
    )


async def test_the_operator_plays_the_people_at_the_locker(tmp_path: Path) -> None:
    """Human colleagues: Zhang lends the stapler over chat; the operator scans Zhang's code and
    shuts the door (deposit), then Lee's (collect); the instruction ends done. A code scanned
    twice is rejected by the lock as replayed."""
    async with serve(tmp_path) as client:
        await client.patch("/v1/people/wang", json={"available": False})
        created = (
            await client.post(
                "/v1/instructions", json={"requester": "lee", "text": "a stapler please"}
            )
        ).json()
        instruction = created["id"]

        def asked_zhang(messages: list[dict[str, object]]) -> bool:
            return any(m["question_id"] for m in messages)

        asked = await _wait_for(client, "/v1/chats/dm/zhang", asked_zhang)
        question = next(m["question_id"] for m in asked if m["question_id"])  # type: ignore[union-attr,index]
        await client.post(
            "/v1/messages",
            json={"sender": "zhang", "text": "Yes, you can have it.", "in_reply_to": question},
        )
        for person in ("zhang", "lee"):
            codes = await _wait_for(
                client,
                "/v1/locker/codes",
                lambda cs, p=person: any(c["person"] == p and c["scannable"] for c in cs),
            )
            code = next(c for c in codes if c["person"] == person)  # type: ignore[union-attr]
            # What the panel shows names people and things (no stapler:zhang, no ins-…).
            assert code["person_name"] == {"zhang": "Zhang Wei", "lee": "Lee Ming"}[person]
            assert (
                code["task"]
                == {
                    "zhang": "put Zhang Wei's stapler into the locker",
                    "lee": "take Zhang Wei's stapler out of the locker",
                }[person]
            )
            scanned = await client.post("/v1/locker/scan", json={"code_id": code["code_id"]})
            assert scanned.status_code == 200
            assert scanned.json()["kind"] == "code_accepted"
            assert scanned.json()["person"] == person
            assert (await client.get("/v1/locker")).json()["door"] == "open"
            again = await client.post("/v1/locker/scan", json={"code_id": code["code_id"]})
            assert again.json()["kind"] == "code_rejected"
            closed = await client.post("/v1/locker/close")
            assert closed.json()["kind"] == "door_closed"
            assert (await client.post("/v1/locker/close")).status_code == 409
        final = await _wait_for(
            client, f"/v1/instructions/{instruction}", lambda b: b["status"] == "done"
        )
        assert final["outcome"] == "done"  # type: ignore[index]
        codes = (await client.get("/v1/locker/codes")).json()
        assert {(c["person"], c["used"]) for c in codes} == {("zhang", True), ("lee", True)}
        unknown = await client.post("/v1/locker/scan", json={"code_id": "no-such-code"})
        assert unknown.status_code == 404
        assert "no-such-code" in unknown.json()["message"]
        assert (await client.post("/v1/locker/scan", json={"code": "x"})).status_code == 422


async def test_the_codes_panel_shows_each_codes_true_state(tmp_path: Path) -> None:
    """issued → scanned the moment the lock accepts it (no Scan button any more) → used once
    the door closes; a cancelled instruction's code is revoked at the lock."""
    async with serve(tmp_path) as client:
        await client.patch("/v1/people/wang", json={"available": False})
        created = await client.post(
            "/v1/instructions", json={"requester": "lee", "text": "a stapler please"}
        )
        instruction = created.json()["id"]
        asked = await _wait_for(
            client, "/v1/chats/dm/zhang", lambda ms: any(m["question_id"] for m in ms)
        )
        question = next(m["question_id"] for m in asked if m["question_id"])  # type: ignore[union-attr,index]
        await client.post(
            "/v1/messages",
            json={"sender": "zhang", "text": "Yes, you can have it.", "in_reply_to": question},
        )

        def state_of(person: str, codes: list[dict[str, object]]) -> object:
            return next((c["state"] for c in codes if c["person"] == person), None)

        codes = await _wait_for(
            client, "/v1/locker/codes", lambda cs: state_of("zhang", cs) == "issued"
        )
        zhang = next(c for c in codes if c["person"] == "zhang")  # type: ignore[union-attr]
        await client.post("/v1/locker/scan", json={"code_id": zhang["code_id"]})
        codes = (await client.get("/v1/locker/codes")).json()
        assert state_of("zhang", codes) == "scanned"  # before the door closes
        await client.post("/v1/locker/close")
        await _wait_for(client, "/v1/locker/codes", lambda cs: state_of("zhang", cs) == "used")

        codes = await _wait_for(
            client, "/v1/locker/codes", lambda cs: state_of("lee", cs) == "issued"
        )
        lee = next(c for c in codes if c["person"] == "lee")  # type: ignore[union-attr]
        await client.post(f"/v1/instructions/{instruction}/cancel")
        await _wait_for(
            client, f"/v1/instructions/{instruction}", lambda b: b["status"] == "cancelled"
        )
        codes = await _wait_for(
            client, "/v1/locker/codes", lambda cs: state_of("lee", cs) == "revoked"
        )
        assert state_of("zhang", codes) == "used"  # type: ignore[arg-type]
        scanned = await client.post("/v1/locker/scan", json={"code_id": lee["code_id"]})
        assert (scanned.json()["kind"], scanned.json()["reason"]) == ("code_rejected", "revoked")
