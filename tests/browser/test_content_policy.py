"""The dashboard works under its own content security policy (issue 24): the live view with
its map, the evaluation tab with its charts and the API docs load, and Chromium reports no
violation of the policy."""

from __future__ import annotations

import pytest
from playwright.sync_api import Browser, ConsoleMessage, expect

from browser.conftest import Server, new_page, sign_in, write_sample_evaluation

pytestmark = pytest.mark.browser


def test_the_dashboard_breaks_none_of_its_content_policy(browser: Browser, server: Server) -> None:
    write_sample_evaluation(server.results_dir)
    page, errors = new_page(browser)
    console: list[str] = []

    def note(message: ConsoleMessage) -> None:
        console.append(message.text)

    page.on("console", note)  # before the page loads: a violation while loading counts
    sign_in(page, server.url)
    expect(page.locator("#map")).to_have_attribute("data-ready", "true", timeout=10_000)
    page.click("#tab-evaluation")
    chart = page.locator("#evaluation figure img").first
    expect(chart).to_be_visible(timeout=30_000)
    page.wait_for_function(
        "img => img.complete && img.naturalWidth > 0", arg=chart.element_handle()
    )
    page.goto(server.url + "/docs")
    expect(page.locator("body")).to_contain_text("/v1/instructions", timeout=10_000)
    violations = [t for t in console if "Content Security Policy" in t or "Refused to" in t]
    assert violations == [] and errors == []
