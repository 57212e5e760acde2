"""The image's exact entry command, parsed from the Dockerfile, serves outside Docker."""

from __future__ import annotations

import json
import shutil
import sys
from pathlib import Path

import httpx
import pytest

from service.server import OPERATOR, base_env, free_port, start

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]


def _dockerfile() -> tuple[list[str], dict[str, str], list[str]]:
    lines = (ROOT / "Dockerfile").read_text().replace("\\\n", " ").splitlines()
    cmd: list[str] = []
    env: dict[str, str] = {}
    exposed: list[str] = []
    for line in lines:
        word, _, rest = line.strip().partition(" ")
        if word == "CMD":
            cmd = json.loads(rest)
        elif word == "ENV":
            for pair in rest.split():
                key, _, value = pair.partition("=")
                env[key] = value
        elif word == "EXPOSE":
            exposed = rest.split()
    return cmd, env, exposed


def test_dockerfile_shape() -> None:
    text = (ROOT / "Dockerfile").read_text()
    cmd, env, exposed = _dockerfile()
    assert cmd[:2] == ["assistantx", "serve"] and "0.0.0.0" in cmd
    assert exposed == ["8000"] and cmd[cmd.index("--port") + 1] == "8000"
    assert "USER assistantx" in text and "HEALTHCHECK" in text and 'VOLUME ["/data"]' in text
    assert env["ASSISTANTX_DATA_DIR"] == "/data"
    # A regular install of the built wheel: the package data, not a source tree, serves.
    assert "pip install -e" not in text and "pip wheel" in text
    for folder in ("src", "dataset", "maps", "prompts"):  # the wheel's package-data links
        assert f"COPY {folder} ./{folder}" in text


def test_the_entry_command_serves(tmp_path: Path) -> None:
    cmd, image_env, _ = _dockerfile()
    port = free_port()  # 8000 may be taken on a shared machine; everything else is exact
    cmd = [*cmd[: cmd.index("--port") + 1], str(port)]
    executable = shutil.which(cmd[0], path=str(Path(sys.executable).parent))
    assert executable is not None
    env = base_env(tmp_path / "data")
    env.update({k: v for k, v in image_env.items() if k != "ASSISTANTX_DATA_DIR"})
    server = start([executable, *cmd[1:]], env, port)
    try:
        assert httpx.get(f"{server.url}/healthz").json() == {"status": "ok"}
        r = httpx.get(f"{server.url}/v1/robot", headers={"Authorization": f"Bearer {OPERATOR}"})
        assert r.status_code == 200 and r.json()["place"]
    finally:
        server.stop()
