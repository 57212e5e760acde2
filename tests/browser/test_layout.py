"""The dashboard's layout at a phone's, a tablet's and a desktop's width (390, 820, 1280 px),
checked on the rendered page by bounding boxes: no panel over another and nothing wider than
the screen; on a phone the form comes first and fits in the first screen; on a tablet the
trace has the full width and is not cut by a scroll box; map labels clear of each other, the
people and the robot; the "As" box acts as the token's own person or asks the operator; and
the Evaluation tab's values stay on one line, with a hint when its table scrolls. Each width's
screenshot is written to test-artifacts/browser/ (the README's with
ASSISTANTX_UPDATE_SCREENSHOTS=1) after its boxes were checked."""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from dataclasses import dataclass

import pytest
from playwright.sync_api import Browser, Page, expect

from browser.conftest import (
    LEE,
    OPERATOR,
    Server,
    new_page,
    started_server,
    write_sample_evaluation,
)
from browser.test_dashboard import shoot
from helpers.eventually import eventually_sync

pytestmark = pytest.mark.browser

HEIGHTS = {390: 844, 820: 1180, 1280: 900}  # a phone, a tablet, a laptop
PANELS = ["instructions", "trace", "map-panel", "people", "chats", "locker"]

Box = dict[str, float]


def _open(browser: Browser, server: Server, width: int, token: str = OPERATOR) -> Page:
    page, errors = new_page(browser, width, HEIGHTS[width])
    page.add_init_script(f"localStorage.setItem('assistantx.token', {json.dumps(token)})")
    page.goto(server.url + "/")
    expect(page.locator("#connection-text")).to_have_text("Live", timeout=15_000)
    expect(page.locator("#map")).to_have_attribute("data-robot", re.compile(r"^[0-9.]+,"))
    assert not errors, errors
    return page


def _box(page: Page, selector: str) -> Box:
    box = page.locator(selector).first.bounding_box()
    assert box is not None, f"{selector} is not rendered"
    return box


def _overlap(a: Box, b: Box) -> bool:
    return (
        a["x"] < b["x"] + b["width"] - 0.5
        and b["x"] < a["x"] + a["width"] - 0.5
        and a["y"] < b["y"] + b["height"] - 0.5
        and b["y"] < a["y"] + a["height"] - 0.5
    )


def _rects_overlap(a: list[float], b: list[float]) -> bool:
    return a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and a[1] < b[1] + b[3] and b[1] < a[1] + a[3]


@dataclass(frozen=True)
class Running:
    server: Server
    instruction: str


@pytest.fixture(scope="module")
def running(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Running]:
    """One server with an instruction that has steps in its trace (the tests play nobody: it
    waits on them), for the three widths: each looks at it, none changes it."""
    with started_server(tmp_path_factory.mktemp("running")) as server:
        created = server.api(
            "POST", "/v1/instructions", json={"requester": "lee", "text": "Bring me a stapler"}
        )
        assert created.status_code == 202, created.text
        ins = created.json()["id"]

        def steps() -> int:
            trace = server.api("GET", f"/v1/instructions/{ins}").json()["trace"]
            return 0 if trace is None else len(trace["steps"])  # none while it waits to start

        eventually_sync(
            lambda: steps() >= 1,
            what="the instruction's first step",
            timeout_s=30,
            interval_s=0.2,
        )
        yield Running(server, ins)


@pytest.fixture(scope="module")
def evaluated(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Server]:
    """One server with the sample evaluation in its results folder, for both widths."""
    with started_server(tmp_path_factory.mktemp("evaluated")) as server:
        write_sample_evaluation(server.results_dir)
        yield server


def _show_the_instruction(page: Page, ins: str) -> None:
    page.click(f'#instruction-list button[data-id="{ins}"]')
    expect(page.locator("#timeline .step").first).to_be_visible(timeout=10_000)


def _panel_boxes(page: Page) -> dict[str, Box]:
    """Every panel's box in one layout of the page: the instruction runs on while the test
    looks (a chat message arrives, a step is added), so boxes read one call at a time may
    come from two layouts, a panel seen before it grew beside one seen after (a CI run saw
    the trace over the chats that way)."""
    found: dict[str, Box | None] = page.evaluate(
        """(names) => Object.fromEntries(names.map((name) => {
            const el = document.querySelector(`#view-live > .${name}`);
            if (!el) return [name, null];
            const r = el.getBoundingClientRect();
            return [name, {x: r.x, y: r.y, width: r.width, height: r.height}];
        }))""",
        PANELS,
    )
    missing = [name for name, box in found.items() if box is None]
    assert not missing, f"{missing} not rendered"
    return {name: box for name, box in found.items() if box is not None}


def _check_common_layout(page: Page, width: int) -> dict[str, Box]:
    assert page.evaluate("document.documentElement.scrollWidth") <= width
    boxes = _panel_boxes(page)
    for i, a in enumerate(PANELS):
        for b in PANELS[i + 1 :]:
            assert not _overlap(boxes[a], boxes[b]), (width, a, b, boxes[a], boxes[b])
        assert boxes[a]["x"] >= 0 and boxes[a]["x"] + boxes[a]["width"] <= width + 0.5, a
    labels = json.loads(page.get_attribute("#map", "data-labels") or "[]")
    marks = json.loads(page.get_attribute("#map", "data-marks") or "[]")
    assert len(labels) >= 8, labels  # most places stay named
    clashes = [
        (a, b) for i, a in enumerate(labels) for b in labels[i + 1 :] if _rects_overlap(a, b)
    ]
    assert not clashes, clashes
    covered = [(a, m) for a in labels for m in marks if _rects_overlap(a, m)]
    assert not covered, covered  # no name under a person's disc or the robot
    return boxes


@pytest.mark.parametrize("width", [390, 820, 1280])
def test_layout_at_three_widths(pages: Browser, running: Running, width: int) -> None:
    page = _open(pages, running.server, width)
    _show_the_instruction(page, running.instruction)
    boxes = _check_common_layout(page, width)
    view = HEIGHTS[width]
    if width == 390:
        # the form first, whole, in the first screen; the map after it
        assert boxes["instructions"]["y"] < boxes["map-panel"]["y"]
        for part in ("#submit-requester", "#submit-text", "#submit-form button[type=submit]"):
            box = _box(page, part)
            assert box["y"] >= 0 and box["y"] + box["height"] <= view, (part, box)
    if width == 820:
        # the trace has the whole width: no empty column beside it, and no scroll box cuts it
        main = _box(page, "#view-live")
        assert boxes["trace"]["width"] >= 0.95 * main["width"], (boxes["trace"], main)
        clipped = page.evaluate(
            "(() => { const t = document.getElementById('timeline');"
            " return t.scrollHeight - t.clientHeight; })()"
        )
        assert clipped <= 1, clipped
    if width == 1280:
        # three columns: the instructions beside the map
        assert (
            boxes["instructions"]["x"] + boxes["instructions"]["width"] <= boxes["map-panel"]["x"]
        )
    shoot(page, f"dashboard-{width}")


def test_the_as_box_is_the_tokens_person_or_asks(browser: Browser, server: Server) -> None:
    operator = _open(browser, server, 1280)
    expect(operator.locator("#submit-requester option")).to_have_count(17)  # 16 + "choose"
    assert operator.input_value("#submit-requester") == ""
    expect(operator.locator("#submit-requester")).to_contain_text("Choose who asks")
    operator.fill("#submit-text", "Bring me a stapler")
    operator.click("#submit-form button[type=submit]")
    # the browser asks for a choice: nothing is submitted as somebody by default
    assert not operator.evaluate("document.getElementById('submit-form').checkValidity()")
    assert server.api("GET", "/v1/instructions").json()["items"] == []
    lee = _open(browser, server, 1280, token=LEE)
    expect(lee.locator("#submit-requester option")).to_have_count(1)
    assert lee.input_value("#submit-requester") == "lee"
    expect(lee.locator("#submit-requester")).to_contain_text("Lee Ming")


@pytest.mark.parametrize("width", [390, 1280])
def test_evaluation_values_stay_on_one_line(pages: Browser, evaluated: Server, width: int) -> None:
    page = _open(pages, evaluated, width)
    page.click("#tab-evaluation")
    cell = page.locator("#evaluation td", has_text="100.0 ± 0.0").first
    expect(cell).to_be_visible(timeout=10_000)
    line = float(cell.evaluate("el => parseFloat(getComputedStyle(el).lineHeight)"))
    height = float(cell.evaluate("el => el.getBoundingClientRect().height"))
    assert height < 1.7 * line, (height, line)  # one line, not "100.0 ±" over "0.0"
    assert page.evaluate("document.documentElement.scrollWidth") <= width
    hint = page.locator("#evaluation .scroll-hint").first
    wrap = page.locator("#evaluation .table-wrap").first
    sizes = wrap.evaluate("el => [el.scrollWidth, el.clientWidth]")
    if width == 390:  # the table is cut by the phone's width: the hint says it scrolls
        assert sizes[0] > sizes[1], sizes
        expect(hint).to_be_visible()
    else:  # the whole table fits: no hint
        assert sizes[0] <= sizes[1], sizes
        expect(hint).to_be_hidden()
    shoot(page, f"evaluation-{width}")
