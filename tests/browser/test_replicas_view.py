"""The dashboard of replicas on one PostgreSQL: a table says each replica's health and which
offices it runs, and follows a takeover (a replica killed: its office moves to the other)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
import yaml
from playwright.sync_api import Browser, expect

from browser.conftest import Server, new_page, sign_in

pytestmark = [pytest.mark.browser, pytest.mark.postgres]


@pytest.fixture
def replicas(tmp_path: Path, postgres_url: str) -> Iterator[tuple[Server, Server]]:
    """Two replicas sharing two offices (copies of the default office): one office each."""
    deployment = tmp_path / "offices.yaml"
    entries = [{"id": "hq", "name": "Headquarters"}, {"id": "annex", "name": "Annex"}]
    deployment.write_text(yaml.safe_dump({"offices": entries}), encoding="utf-8")
    servers: list[Server] = []
    try:
        for name in ("replica-a", "replica-b"):
            (tmp_path / name).mkdir()
            env = {
                "ASSISTANTX_OFFICES": str(deployment),
                "ASSISTANTX_DATABASE_URL": postgres_url,
                "ASSISTANTX_REPLICA_ID": name,
                "ASSISTANTX_LEASE_TTL_S": "2",
                "ASSISTANTX_LOCK_SHARED_KEY": "the browser test's shared lock key",
                "ASSISTANTX_TOKENS": "",
                "ASSISTANTX_ROBOT": "sim",
            }
            server = Server(tmp_path / name, tmp_path / "results", env=env)
            servers.append(server)
            server.start()
        yield servers[0], servers[1]
    finally:
        for server in servers:
            server.stop()


@pytest.fixture
def server(replicas: tuple[Server, Server]) -> Server:
    """The page's server, replica A (the ``browser`` fixture closes the pages before the
    replicas stop); without it, ``browser`` would start a third server nobody uses."""
    return replicas[0]


def test_the_replicas_table_shows_health_and_offices_and_follows_a_takeover(
    browser: Browser, replicas: tuple[Server, Server]
) -> None:
    a, b = replicas
    page, errors = new_page(browser)
    sign_in(page, a.url, live=False)  # the page follows the replicas, not an office
    table = page.locator("#replicas-table")
    expect(table).to_be_visible(timeout=20_000)
    row_a = table.locator('tr[data-replica="replica-a"] td')
    row_b = table.locator('tr[data-replica="replica-b"] td')
    # One office each once B has joined (the page refreshes every few seconds).
    expect(row_a.nth(0)).to_have_text("replica-a (answering this page)", timeout=30_000)
    expect(row_a.nth(1)).to_contain_text("up")
    expect(row_b.nth(1)).to_contain_text("up", timeout=30_000)
    expect(row_a.nth(2)).not_to_have_text("no office", timeout=30_000)
    expect(row_b.nth(2)).not_to_have_text("no office", timeout=30_000)
    ran_by_b = row_b.nth(2).inner_text()
    assert ran_by_b in ("Headquarters", "Annex"), ran_by_b

    b.stop(crash=True)  # kill -9: its office moves to A once its lease expired
    expect(row_a.nth(2)).to_have_text("Headquarters, Annex", timeout=60_000)
    expect(table.locator('tr[data-replica="replica-b"]')).to_have_count(0, timeout=60_000)
    assert not errors, errors
