"""/docs in a browser shows what to send: the instruction body's fields, their meaning and an
example, drawn from the service's own /openapi.json."""

from __future__ import annotations

import json

import pytest
from playwright.sync_api import Browser, expect

from browser.conftest import Server

pytestmark = pytest.mark.browser


def test_docs_show_the_instruction_fields_and_an_example(browser: Browser, server: Server) -> None:
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    page.goto(server.url + "/docs")
    submit = page.locator('section.operation[data-method="post"][data-path="/v1/instructions"]')
    expect(submit).to_be_visible(timeout=15_000)
    fields = submit.locator("ul.fields li")
    expect(fields).to_have_count(2)
    expect(fields.first).to_contain_text("requester (string, required)")
    expect(fields.nth(1)).to_contain_text("text (string, required) — the instruction in words")
    example = json.loads(submit.locator("pre.example").inner_text())
    assert example == {"requester": "lee", "text": "Bring me a stapler"}
    expect(submit).to_contain_text("Content-Type: application/json")
