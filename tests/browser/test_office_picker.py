"""The dashboard of a deployment of several offices: a picker chooses the office, and every
panel then shows that office's people, map and instructions (kept for the next visit)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
import yaml
from playwright.sync_api import Browser, expect

from browser.conftest import ROOT, Server, new_page, sign_in

pytestmark = pytest.mark.browser

HARBOUR = ROOT / "dataset" / "offices" / "harbour"


@pytest.fixture
def server(tmp_path: Path) -> Iterator[Server]:
    """Two offices: headquarters (the default office, 16 people) and Harbour Street (18)."""
    deployment = tmp_path / "offices.yaml"
    entries = [
        {"id": "hq", "name": "Headquarters"},
        {
            "id": "harbour",
            "name": "Harbour Street",
            "office": str(HARBOUR / "office.yaml"),
            "map_anchors": str(HARBOUR / "office.anchors.yaml"),
        },
    ]
    deployment.write_text(yaml.safe_dump({"offices": entries}), encoding="utf-8")
    (tmp_path / "data").mkdir()
    env = {
        "ASSISTANTX_OFFICES": str(deployment),
        "ASSISTANTX_TOKENS": "",
        "ASSISTANTX_ROBOT": "sim",
    }
    srv = Server(tmp_path / "data", tmp_path / "results", env=env)
    srv.start()
    try:
        yield srv
    finally:
        srv.stop()


def test_the_picker_switches_the_page_to_another_office(browser: Browser, server: Server) -> None:
    page, errors = new_page(browser)
    sign_in(page, server.url)
    picker = page.locator("#office-select")
    expect(picker).to_be_visible()
    expect(picker.locator("option")).to_have_text(["Headquarters", "Harbour Street"])
    expect(picker).to_have_value("hq")
    expect(page.locator("#people-table tbody tr")).to_have_count(16)
    expect(page.locator('#submit-requester option[value="lee"]')).to_have_count(1)

    page.select_option("#office-select", "harbour")  # the page starts over on Harbour Street
    expect(page.locator("#people-table tbody tr")).to_have_count(18)
    expect(page.locator('#submit-requester option[value="will"]')).to_have_count(1)
    expect(page.locator('#submit-requester option[value="lee"]')).to_have_count(0)
    expect(page.locator("#connection-text")).to_have_text("Live", timeout=10_000)
    expect(page.locator("#map")).to_have_attribute("data-ready", "true")

    # The page asks Harbour Street's own API: an instruction sent from it is Harbour's.
    page.select_option("#submit-requester", "will")
    page.fill("#submit-text", "Please bring me a stapler.")
    page.click("#submit-form button[type=submit]")
    expect(page.locator("#instruction-list button")).to_have_count(1)
    harbour = server.api("GET", "/v1/offices/harbour/instructions").json()["items"]
    hq = server.api("GET", "/v1/offices/hq/instructions").json()["items"]
    assert [i["requester"] for i in harbour] == ["will"] and hq == []

    page.reload()  # the choice is kept
    expect(picker).to_have_value("harbour")
    expect(page.locator("#people-table tbody tr")).to_have_count(18)
    assert not errors, errors
