"""The dashboard of an office with two robots (ASSISTANTX_ROBOTS=2), in Chromium: both robots
on the map, numbered, and each one's doing in the status line."""

from __future__ import annotations

import re
from collections.abc import Iterator
from pathlib import Path

import pytest
from playwright.sync_api import Browser, expect

from browser.conftest import Server
from browser.test_dashboard import open_dashboard, shoot

pytestmark = pytest.mark.browser


@pytest.fixture
def server(tmp_path: Path) -> Iterator[Server]:
    """This module's server: an office with two robots."""
    (tmp_path / "data").mkdir()
    srv = Server(tmp_path / "data", tmp_path / "results", env={"ASSISTANTX_ROBOTS": "2"})
    srv.start()
    try:
        yield srv
    finally:
        srv.stop()


def test_two_robots_are_drawn_numbered_and_described(browser: Browser, server: Server) -> None:
    page = open_dashboard(browser, server)
    marker = r"[0-9.]+,[0-9.]+"
    expect(page.locator("#map")).to_have_attribute(
        "data-robots", re.compile(rf"^{marker};{marker}$")
    )
    first, second = (page.get_attribute("#map", "data-robots") or "").split(";")
    assert first == page.get_attribute("#map", "data-robot")  # robot 1 as one robot shows
    assert first != second
    status = page.locator("#robot-status")
    expect(status).to_contain_text("Robot 1: at Meeting room")
    expect(status).to_contain_text("Robot 2: at parking 2")
    robots = server.api("GET", "/v1/robots").json()
    assert [r["name"] for r in robots] == ["robot 1", "robot 2"]
    shoot(page, "dashboard-two-robots")
