"""Debian's Chromium through Playwright, and the real server as a subprocess.

Browser tests never download a browser: they drive ``/usr/bin/chromium`` (installed by
``.ci/install-browser``) and are skipped, loudly, where it is missing. Screenshots go to
``test-artifacts/`` (gitignored); with ``ASSISTANTX_UPDATE_SCREENSHOTS=1`` the README's
images in ``docs/screenshots/`` are rewritten too.
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import signal
import subprocess
import sys
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import httpx
import pytest
from playwright.sync_api import Browser, Page, Playwright, expect, sync_playwright

from helpers.processes import wait_ready
from helpers.servers import free_port

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]
ARTIFACTS = ROOT / "test-artifacts" / "browser"
SCREENSHOTS = ROOT / "docs" / "screenshots"
OPERATOR = "operator-token-for-browser-tests"
LEE = "lee-token-for-browser-tests-01"  # a person's token: Lee's own


def _reasoner_env() -> dict[str, str]:
    """The embedded default reasoner once it exists; until then the service tests' scripted
    stapler reasoner, which plays the same L2 instruction."""
    import assistantx.agents.symbolic

    if hasattr(assistantx.agents.symbolic, "build_factory"):
        return {}
    return {
        "ASSISTANTX_REASONER_BUILDER": "stapler_reasoner:build_factory",
        "PYTHONPATH": os.pathsep.join([str(ROOT / "tests" / "service"), str(ROOT / "tests")]),
    }


@dataclass
class Server:
    """``python -m assistantx serve`` on a fixed port and data directory; restartable."""

    data_dir: Path
    results_dir: Path
    port: int = field(default_factory=free_port)
    process: subprocess.Popen[bytes] | None = None
    env: dict[str, str] = field(default_factory=dict)  # more ASSISTANTX_* settings

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.port}"

    def start(self, timeout_s: float = 90.0) -> None:  # start-up took 19-23 s on a loaded machine
        env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
        env.update(
            {
                "ASSISTANTX_DATA_DIR": str(self.data_dir),
                "ASSISTANTX_RESULTS_DIR": str(self.results_dir),
                "ASSISTANTX_OPERATOR_TOKEN": OPERATOR,
                "ASSISTANTX_TOKENS": json.dumps({LEE: "lee"}),
                "ASSISTANTX_PEOPLE": "human",  # the test plays the colleagues
                "ASSISTANTX_SPEEDUP": "50",
                **_reasoner_env(),
                **self.env,
            }
        )
        cmd = [sys.executable, "-m", "assistantx", "serve", "--host", "127.0.0.1"]
        with (self.data_dir.parent / f"server-{self.port}.log").open("ab") as log:
            # The child keeps its own copy of the descriptor.
            self.process = subprocess.Popen(
                [*cmd, "--port", str(self.port)], env=env, stdout=log, stderr=log
            )
        try:
            wait_ready(self.process, f"{self.url}/readyz", timeout_s=timeout_s)
        except AssertionError as exc:
            self.stop()  # reaped now, not warned about by a later test's garbage collection
            raise RuntimeError(f"server did not become ready: {exc}") from None

    def stop(self, *, crash: bool = False) -> None:
        """Stop gracefully (SIGTERM), or as a crash would (SIGKILL): connections just drop."""
        if self.process is not None and self.process.poll() is None:
            self.process.send_signal(signal.SIGKILL if crash else signal.SIGTERM)
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(10)
        self.process = None

    def api(self, method: str, path: str, **kwargs: object) -> httpx.Response:
        headers = {"Authorization": f"Bearer {OPERATOR}"}
        return httpx.request(method, f"{self.url}{path}", headers=headers, timeout=10, **kwargs)  # type: ignore[arg-type]


@contextlib.contextmanager
def started_server(root: Path, **env: str) -> Iterator[Server]:
    """A server on its own data and results folders under ``root``, stopped at the end."""
    (root / "data").mkdir()
    srv = Server(root / "data", root / "results", env=env)
    srv.start()
    try:
        yield srv
    finally:
        srv.stop()


@pytest.fixture
def server(tmp_path: Path) -> Iterator[Server]:
    with started_server(tmp_path) as srv:
        yield srv


@pytest.fixture(scope="module")
def module_server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Server]:
    """One server for the tests of a module that only look: they submit nothing and change
    nobody, so a start (2-3 CPU-s, seconds of wall time) serves them all."""
    with started_server(tmp_path_factory.mktemp("module-server")) as srv:
        yield srv


@pytest.fixture(scope="module")
def playwright() -> Iterator[Playwright]:
    # Module scope: the sync API keeps an event loop running on this thread until it exits,
    # and the asyncio tests collected after this folder need the thread's loop free again.
    if not CHROMIUM.exists():
        pytest.fail(f"{CHROMIUM} is missing: run .ci/install-browser")
    with sync_playwright() as p:
        yield p


@pytest.fixture(scope="module")
def chromium(playwright: Playwright) -> Iterator[Browser]:
    """One Chromium for a module's tests: a launch costs about a second of CPU, a page in a
    running browser a fraction of that. Each test's pages have their own contexts (cookies,
    storage), closed after the test by ``browser``."""
    browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
    try:
        yield browser
    finally:
        browser.close()


@contextlib.contextmanager
def closing_pages(chromium: Browser) -> Iterator[Browser]:
    try:
        yield chromium
    finally:
        for context in chromium.contexts:
            context.close()


@pytest.fixture
def browser(chromium: Browser, server: Server) -> Iterator[Browser]:
    # Depends on the server so that the test's pages close first: an open event stream would
    # hold up the server's graceful shutdown.
    with closing_pages(chromium) as browser:
        yield browser


@pytest.fixture
def pages(chromium: Browser) -> Iterator[Browser]:
    """``browser`` for a test on a server that outlives it (``module_server``): the test's
    pages are closed at its end all the same, long before that server stops."""
    with closing_pages(chromium) as browser:
        yield browser


def new_page(browser: Browser, width: int = 1366, height: int = 900) -> tuple[Page, list[str]]:
    """A page at this viewport, and the list its uncaught script errors go into."""
    page = browser.new_page(viewport={"width": width, "height": height})
    errors: list[str] = []
    page.on("pageerror", lambda exc: errors.append(str(exc)))
    return page, errors


def give_token(page: Page, token: str) -> None:
    """Types the token into the dashboard's dialog and sends it, as a person does."""
    page.fill("#token-input", token)
    page.click("#token-form button[type=submit]")


def sign_in(page: Page, url: str, token: str = OPERATOR, *, live: bool = True) -> None:
    """Opens the dashboard at ``url``, which asks for a token, gives it, and (``live``) waits
    until the page is live, its event stream open: not on a replica that runs no office yet."""
    page.goto(url + "/")
    expect(page.locator("#token-dialog")).to_be_visible()
    give_token(page, token)
    if live:
        expect(page.locator("#connection-text")).to_have_text("Live", timeout=10_000)


def screenshot_targets(name: str) -> list[Path]:
    """Where a screenshot goes: the test artifacts, and the README's images when asked."""
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    targets = [ARTIFACTS / f"{name}.png"]
    if os.environ.get("ASSISTANTX_UPDATE_SCREENSHOTS") == "1":
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        targets.append(SCREENSHOTS / f"{name}.png")
    return targets


def write_sample_evaluation(results_dir: Path) -> None:
    """The committed evaluation of the embedded reasoner, as the evaluator wrote it."""
    source = Path(__file__).resolve().parents[2] / "results" / "ppdr-symbolic"
    shutil.copytree(source, results_dir / "ppdr-symbolic")
