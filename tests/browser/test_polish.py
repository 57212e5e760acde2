"""Dashboard details a user noticed: one true state for a cancelled instruction, map labels that
never overlap on a phone, availability toggles that look pressable, and an Evaluation tab that
says what its metrics mean."""

from __future__ import annotations

import json

import pytest
from playwright.sync_api import Browser, expect

from browser.conftest import Server, write_sample_evaluation
from browser.test_dashboard import open_dashboard, shoot
from helpers.eventually import eventually_sync

pytestmark = pytest.mark.browser


def test_a_cancelled_instruction_shows_one_state(browser: Browser, server: Server) -> None:
    page = open_dashboard(browser, server)
    created = server.api(
        "POST", "/v1/instructions", json={"requester": "lee", "text": "Bring me a stapler"}
    )
    assert created.status_code == 202, created.text
    ins = created.json()["id"]
    button = page.locator(f'#instruction-list button[data-id="{ins}"]')
    expect(button).to_be_visible(timeout=10_000)
    eventually_sync(
        lambda: server.api("GET", f"/v1/instructions/{ins}").json()["status"] != "queued",
        what="the instruction to leave the queue",
        timeout_s=20,
        interval_s=0.1,
    )
    assert server.api("POST", f"/v1/instructions/{ins}/cancel").status_code == 200
    expect(button).to_have_attribute("data-status", "cancelled", timeout=10_000)
    record = server.api("GET", f"/v1/instructions/{ins}").json()
    assert record["status"] == "cancelled"
    badges = button.locator(".badge")
    expect(badges).to_have_count(1, timeout=10_000)
    expect(badges).to_have_text("cancelled")
    button.click()
    header = page.locator("#trace-header .badge")
    expect(header).to_have_count(1, timeout=10_000)
    expect(header).to_have_text("cancelled")
    expect(page.locator("#map")).to_have_attribute("data-path", "0")


def _overlap(a: list[float], b: list[float]) -> bool:
    return a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and a[1] < b[1] + b[3] and b[1] < a[1] + a[3]


def test_map_labels_do_not_overlap_on_a_phone(pages: Browser, module_server: Server) -> None:
    page = open_dashboard(pages, module_server, width=390)
    page.locator("#map").scroll_into_view_if_needed()
    labels = json.loads(page.get_attribute("#map", "data-labels") or "[]")
    width = page.evaluate("document.getElementById('map').clientWidth")
    assert width <= 390
    assert len(labels) >= 8, labels  # most places stay named
    clashes = [(a, b) for i, a in enumerate(labels) for b in labels[i + 1 :] if _overlap(a, b)]
    assert not clashes, clashes
    assert all(0 <= x and x + w <= width + 0.5 for x, _, w, _ in labels)
    assert page.evaluate("document.documentElement.scrollWidth") <= 390
    shoot(page, "dashboard-phone")


def test_availability_toggles_look_pressable(pages: Browser, module_server: Server) -> None:
    page = open_dashboard(pages, module_server)
    toggle = page.locator('#people-table tr[data-person="gao"] button')
    style = toggle.evaluate(
        """el => {
            const s = getComputedStyle(el), knob = getComputedStyle(el, '::before');
            return {cursor: s.cursor, radius: parseFloat(s.borderTopLeftRadius),
                    border: parseFloat(s.borderTopWidth), knob: knob.content,
                    knobWidth: parseFloat(knob.width), height: el.getBoundingClientRect().height};
        }"""
    )
    assert style["cursor"] == "pointer"
    assert style["radius"] >= style["height"] / 2 - 1  # a pill, not a tag
    assert style["border"] >= 2
    assert style["knob"] != "none" and style["knobWidth"] > 8  # the switch's knob
    before = toggle.evaluate("el => getComputedStyle(el).boxShadow")
    toggle.hover()
    assert toggle.evaluate("el => getComputedStyle(el).boxShadow") != before


def test_a_refresh_keeps_the_rows_that_did_not_change(browser: Browser, server: Server) -> None:
    """A toggle is never swapped out from under a pointer: when one person changes, the other
    rows stay the very same elements (a redraw of every row used to detach them)."""
    page = open_dashboard(browser, server)
    gao = page.locator('#people-table tr[data-person="gao"] button')
    gao.evaluate("el => { el.dataset.probe = 'kept'; }")
    changed = server.api(
        "PATCH",
        "/v1/people/zhang",
        json={"available": False, "evidence": "out for lunch"},
    )
    assert changed.status_code == 200, changed.text
    zhang = page.locator('#people-table tr[data-person="zhang"] button')
    expect(zhang).to_have_attribute("aria-pressed", "false", timeout=10_000)
    expect(zhang).to_have_text("unavailable")
    expect(gao).to_have_attribute("data-probe", "kept")


def test_the_evaluation_tab_explains_its_metrics(browser: Browser, server: Server) -> None:
    write_sample_evaluation(server.results_dir)
    page = open_dashboard(browser, server)
    page.click("#tab-evaluation")
    terms = page.locator("#evaluation .metric-glossary dt")
    expect(terms).to_have_text(["SR", "CR", "RR", "CTA", "RTA"], timeout=30_000)
    glossary = page.locator("#evaluation .metric-glossary")
    expect(glossary).to_contain_text("success rate")
    expect(glossary).to_contain_text("redundant actions")
    expect(page.locator("#evaluation figcaption", has_text="RR")).to_have_text(
        "RR — redundancy rate by level (%)"
    )
