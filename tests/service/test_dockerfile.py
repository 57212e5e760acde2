"""The image's exact entry command, parsed from the Dockerfile, serves outside Docker; and the
Dockerfile's shape, read statically (no Docker daemon on the test machines): a final stage
with nothing but the built virtualenv on a slim Python, and the HEALTHCHECK's format caveat."""

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
    lines = _instructions((ROOT / "Dockerfile").read_text())
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


def _instructions(text: str) -> list[str]:
    """One line per instruction: comment lines dropped, continuations joined."""
    kept = [line for line in text.splitlines() if not line.lstrip().startswith("#")]
    return "\n".join(kept).replace("\\\n", " ").splitlines()


def _stages() -> list[list[str]]:
    stages: list[list[str]] = []
    for line in _instructions((ROOT / "Dockerfile").read_text()):
        if line.startswith("FROM "):
            stages.append([])
        if stages and line.strip():
            stages[-1].append(line.strip())
    return stages


def test_the_final_stage_holds_only_the_built_virtualenv() -> None:
    stages = _stages()
    assert len(stages) == 2
    build, final = stages
    assert build[0].endswith(" AS build")
    assert final[0] == "FROM python:3.11-slim"  # a fresh slim base, not the build stage
    text = "\n".join(final)
    copies = [line for line in final if line.startswith("COPY")]
    assert copies == ["COPY --from=build /opt/venv /opt/venv"]  # no source, no wheels
    for tool in ("apt-get", "gcc", "build-essential", "pip ", "wheel"):
        assert tool not in text, tool
    env = dict(
        pair.partition("=")[::2]
        for line in final
        if line.startswith("ENV ")
        for pair in line.split()[1:]
    )
    assert env["PATH"].startswith("/opt/venv/bin:")
    # the build stage installs binary wheels only: no compiler is needed anywhere
    assert any("--only-binary=:all:" in line for line in build)


def test_the_healthcheck_format_caveat_is_stated() -> None:
    dockerfile = (ROOT / "Dockerfile").read_text()
    readme = (ROOT / "README.md").read_text()
    assert "HEALTHCHECK" in dockerfile
    for text in (dockerfile, readme):
        assert "podman build --format docker" in text
        assert "OCI" in text


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
    # The image's PATH names its own /opt/venv; here the test's virtualenv plays it.
    env.update({k: v for k, v in image_env.items() if k not in ("ASSISTANTX_DATA_DIR", "PATH")})
    server = start([executable, *cmd[1:]], env, port)
    try:
        assert httpx.get(f"{server.url}/healthz").json() == {"status": "ok"}
        r = httpx.get(f"{server.url}/v1/robot", headers={"Authorization": f"Bearer {OPERATOR}"})
        assert r.status_code == 200 and r.json()["place"]
    finally:
        server.stop()
