"""Several offices in one deployment (``ASSISTANTX_OFFICES``), and one office as before.

Each office has its own people, robot, memory and journal; ``/v1/offices/{office}/...`` is
that office's API; a token of one office is refused on another (403, one line); paths without
an office are the home office's, so a single-office deployment's URLs stay as they were."""

from __future__ import annotations

import json
import sqlite3
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Any

import httpx
import pytest
import yaml

from assistantx.core.errors import JournalError
from assistantx.core.office import DEFAULT_OFFICE
from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from assistantx.service.offices.deployment import (
    OFFICE_STATE,
    DeploymentError,
    claim_journal,
    load_deployment,
    scoped_url,
)
from assistantx.store.journal import Journal
from helpers.servers import serving_app
from service.server import LEE, OPERATOR

HARBOUR = DEFAULT_OFFICE.parent / "offices" / "harbour"
HQ_OPERATOR = "hq-operator-token-000001"
WILL = "will-token-for-tests-0001"
DEPLOYMENT: dict[str, Any] = {
    "offices": [
        {
            "id": "hq",
            "name": "Headquarters",
            "operator_token": HQ_OPERATOR,
            "tokens": {LEE: "lee"},
        },
        {
            "id": "harbour",
            "name": "Harbour Street",
            "office": str(HARBOUR / "office.yaml"),
            "map_anchors": str(HARBOUR / "office.anchors.yaml"),
            "tokens": {WILL: "will"},
        },
    ]
}


def bearer(token: str) -> dict[str, str]:
    return {"Authorization": f"Bearer {token}"}


def write_deployment(folder: Path, deployment: dict[str, Any] = DEPLOYMENT) -> Path:
    path = folder / "offices.yaml"
    path.write_text(yaml.safe_dump(deployment), encoding="utf-8")
    return path


@asynccontextmanager
async def two_offices(tmp_path: Path) -> AsyncIterator[httpx.AsyncClient]:
    settings = Settings(
        data_dir=tmp_path / "data",
        offices=write_deployment(tmp_path),
        operator_token=OPERATOR,
        speedup=50,
        robot="sim",
    )
    async with serving_app(create_app(settings)) as api:
        yield api


async def submit(api: httpx.AsyncClient, path: str, token: str, requester: str) -> str:
    body = {"requester": requester, "text": "Please bring me a stapler."}
    r = await api.post(path, json=body, headers=bearer(token))
    assert r.status_code == 202, r.text
    return str(r.json()["id"])


async def test_each_office_has_its_own_people_instructions_and_journal(tmp_path: Path) -> None:
    async with two_offices(tmp_path) as api:
        r = await api.get("/v1/offices", headers=bearer(OPERATOR))
        assert r.status_code == 200, r.text
        listed = {o["id"]: o for o in r.json()}
        assert set(listed) == {"hq", "harbour"}
        assert listed["harbour"]["name"] == "Harbour Street"
        assert all(o["status"] == "ready" and o["here"] for o in listed.values())
        assert listed["hq"]["replica"] == listed["harbour"]["replica"]  # one process runs both

        # People are the office's own: Will works at Harbour Street, not at headquarters.
        will = await api.get("/v1/offices/harbour/people/will", headers=bearer(OPERATOR))
        assert will.status_code == 200 and will.json()["name"].startswith("Will")
        nobody = await api.get("/v1/offices/hq/people/will", headers=bearer(OPERATOR))
        assert nobody.status_code == 422  # an unknown person, as any name nobody has

        at_harbour = await submit(api, "/v1/offices/harbour/instructions", WILL, "will")
        at_hq = await submit(api, "/v1/offices/hq/instructions", LEE, "lee")

        async def ids(path: str) -> set[str]:
            r = await api.get(path, headers=bearer(OPERATOR))
            assert r.status_code == 200, r.text
            return {i["id"] for i in r.json()["items"]}

        assert await ids("/v1/offices/harbour/instructions") == {at_harbour}
        assert await ids("/v1/offices/hq/instructions") == {at_hq}
        # A path without an office is the home office's (the first listed).
        assert await ids("/v1/instructions") == {at_hq}
        r = await api.get(f"/v1/offices/hq/instructions/{at_harbour}", headers=bearer(OPERATOR))
        assert r.status_code == 404

        # /metrics says which replica runs each office; each office has its own series.
        text = (await api.get("/metrics", headers=bearer(OPERATOR))).text
        replica = listed["hq"]["replica"]
        for office in ("hq", "harbour"):
            assert f'assistantx_office_replica{{office="{office}",replica="{replica}"}} 1.0' in text
            assert f'assistantx_office_ready{{office="{office}"}} 1.0' in text
        harbour_metrics = await api.get("/v1/offices/harbour/metrics", headers=bearer(OPERATOR))
        assert harbour_metrics.status_code == 200
        assert "assistantx_http_requests_total" in harbour_metrics.text
        ready = (await api.get("/readyz")).json()
        assert ready == {
            "status": "ready",
            "replica": replica,
            "offices": {"hq": "ready", "harbour": "ready"},
        }
        assert (await api.get("/v1/offices/harbour/readyz")).json()["status"] == "ready"

    # The rows are apart: the home office's journal is where one office keeps it, the
    # other's in its own folder.
    def journaled(path: Path) -> set[str]:
        with sqlite3.connect(path) as db:
            return {row[0] for row in db.execute("SELECT id FROM instructions")}

    assert journaled(tmp_path / "data" / "journal.sqlite3") == {at_hq}
    with sqlite3.connect(tmp_path / "data" / "journal.sqlite3") as db:
        [(claim,)] = db.execute("SELECT body FROM state WHERE name=?", (OFFICE_STATE,))
    assert json.loads(claim) == {"id": "hq"}  # the journal knows whose it is
    assert journaled(tmp_path / "data" / "offices" / "harbour" / "journal.sqlite3") == {at_harbour}


async def test_a_token_of_one_office_is_refused_on_another_in_one_line(tmp_path: Path) -> None:
    async with two_offices(tmp_path) as api:
        r = await api.get("/v1/offices/hq/me", headers=bearer(WILL))
        assert r.status_code == 403
        detail = r.json()["message"]
        assert detail == "this token is for the office Harbour Street, not Headquarters"
        r = await api.get("/v1/offices/harbour/instructions", headers=bearer(HQ_OPERATOR))
        assert r.status_code == 403
        assert "Headquarters" in r.json()["message"]
        # The home office's paths are headquarters': Will's token is refused there too.
        assert (await api.get("/v1/me", headers=bearer(WILL))).status_code == 403
        # Each token lists only its own office; the deployment operator's lists both.
        r = await api.get("/v1/offices", headers=bearer(WILL))
        assert [o["id"] for o in r.json()] == ["harbour"]
        r = await api.get("/v1/offices", headers=bearer(HQ_OPERATOR))
        assert [o["id"] for o in r.json()] == ["hq"]
        me = await api.get("/v1/offices/harbour/me", headers=bearer(WILL))
        assert me.status_code == 200 and me.json()["person"] == "will"
        # A stranger's token is a 401, as before; an unknown office a 404.
        stranger = await api.get("/v1/offices/hq/me", headers=bearer("x" * 24))
        assert stranger.status_code == 401
        r = await api.get("/v1/offices/nowhere/me", headers=bearer(OPERATOR))
        assert r.status_code == 404 and r.json()["message"] == "no office 'nowhere'"


async def test_one_office_keeps_its_urls_and_is_listed_as_the_default(tmp_path: Path) -> None:
    settings = Settings(
        data_dir=tmp_path,
        operator_token=OPERATOR,
        tokens=json.dumps({LEE: "lee"}),
        speedup=50,
        robot="sim",
    )
    async with serving_app(create_app(settings)) as api:
        iid = await submit(api, "/v1/instructions", LEE, "lee")
        r = await api.get("/v1/offices", headers=bearer(LEE))
        assert r.status_code == 200, r.text
        [office] = r.json()
        assert (office["id"], office["status"], office["here"]) == ("default", "ready", True)
        r = await api.get("/v1/offices/default/instructions", headers=bearer(OPERATOR))
        assert [i["id"] for i in r.json()["items"]] == [iid]
        r = await api.get(f"/v1/instructions/{iid}", headers=bearer(LEE))
        assert r.status_code == 200 and r.json()["requester"] == "lee"
        ready = (await api.get("/readyz")).json()
        assert ready["status"] == "ready" and "offices" not in ready


@pytest.mark.parametrize(
    ("deployment", "problem"),
    [
        ({"offices": []}, "needs 'offices:'"),
        ({"offices": [{"id": "Big Office"}]}, "'id' must be lower-case"),
        ({"offices": [{"id": "a"}, {"id": "a"}]}, "the id 'a' is listed twice"),
        ({"offices": [{"id": "a", "port": 9}]}, "'port' is the deployment's"),
        ({"offices": [{"id": "a", "colour": "red"}]}, "'colour' is no setting"),
        ({"offices": [{"id": "a", "lock_port": "x"}]}, "lock_port"),
    ],
)
def test_a_bad_deployment_file_is_one_line_naming_the_office(
    tmp_path: Path, deployment: dict[str, Any], problem: str
) -> None:
    path = write_deployment(tmp_path, deployment)
    with pytest.raises(DeploymentError, match=problem) as caught:
        load_deployment(Settings(offices=path))
    assert str(caught.value).startswith(str(path)) and "\n" not in str(caught.value)


def test_each_office_but_the_home_one_has_its_own_folder_and_schema(tmp_path: Path) -> None:
    url = "postgresql://assistantx:secret@db:5432/assistantx"
    specs = load_deployment(
        Settings(offices=write_deployment(tmp_path), data_dir=tmp_path / "d", database_url=url)
    )
    home, harbour = specs
    assert (home.settings.data_dir, home.settings.database) == (tmp_path / "d", url)
    assert harbour.settings.data_dir == tmp_path / "d" / "offices" / "harbour"
    assert harbour.settings.database == scoped_url(url, "office_harbour")
    assert harbour.settings.database is not None
    assert harbour.settings.database.endswith("?options=-c%20search_path%3Doffice_harbour%2Cpublic")
    assert harbour.settings.office == HARBOUR / "office.yaml"


def test_a_journal_of_one_office_is_refused_to_another(tmp_path: Path) -> None:
    """Listing another office first would give it the home office's journal: refused."""
    journal = Journal.open(tmp_path / "journal.sqlite3")
    try:
        claim_journal(journal, "hq", "data/journal.sqlite3")  # a single office's journal
        claim_journal(journal, "hq", "data/journal.sqlite3")  # its own again: fine
        with pytest.raises(JournalError) as refused:
            claim_journal(journal, "harbour", "data/journal.sqlite3")
    finally:
        journal.close()
    assert str(refused.value) == (
        "data/journal.sqlite3: this journal belongs to office 'hq', not 'harbour': keep the"
        " office that was listed first in the deployment file first"
    )


async def test_with_no_operator_token_one_is_generated_for_every_office(tmp_path: Path) -> None:
    settings = Settings(
        data_dir=tmp_path / "data", offices=write_deployment(tmp_path), speedup=50, robot="sim"
    )
    app = create_app(settings)
    async with serving_app(app) as api:
        generated = app.state.offices.generated_token
        assert generated == (tmp_path / "data" / "operator-token").read_text().strip()
        r = await api.get("/v1/offices", headers=bearer(generated))
        assert [o["id"] for o in r.json()] == ["hq", "harbour"]
        r = await api.get("/v1/offices/harbour/instructions", headers=bearer(generated))
        assert r.status_code == 200
    # No office generated a token of its own: one token, the deployment's.
    assert not (tmp_path / "data" / "offices" / "harbour" / "operator-token").exists()
