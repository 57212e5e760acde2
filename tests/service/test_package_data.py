"""A built wheel carries the default office, map and prompts, and an installed package finds
them from any directory (no source tree next to it)."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`. Both
# tests read the one wheel the module builds (pip, 6-7 s): on one worker it is built once.
pytestmark = [pytest.mark.slow, pytest.mark.shares_worker("wheel")]

ROOT = Path(__file__).resolve().parents[2]
CANONICAL = ["dataset/office.yaml", "maps/office.yaml", "maps/office.pgm"]
CANONICAL += ["maps/office.anchors.yaml", "prompts/decision.md", "prompts/baselines/react.md"]

PROBE = """
import json, assistantx
from assistantx.adapters.robot.navigator import DEFAULT_MAP, NavigatorRobot
from assistantx.core.clock import SimClock
from assistantx.core.office import DEFAULT_OFFICE, load_office
from assistantx.agents.llm.prompts import DEFAULT_PROMPTS
office = load_office()
robot = NavigatorRobot.from_files(office, SimClock(), localize=False)
print(json.dumps({
    "package": assistantx.__file__,
    "paths": [str(DEFAULT_OFFICE), str(DEFAULT_MAP), str(DEFAULT_PROMPTS)],
    "people": len(office.people),
    "metres": robot.path_distance(office.robot.home, office.person("lee").location),
    "prompts": sorted(p.name for p in DEFAULT_PROMPTS.glob("*.md")),
}))
"""


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Built from a copy of the tree (links kept), so the shared checkout gets no build/."""
    tree = tmp_path_factory.mktemp("tree")
    for name in ("pyproject.toml", "README.md", "src", "dataset", "maps", "prompts"):
        source = ROOT / name
        if source.is_dir():
            ignore = shutil.ignore_patterns("__pycache__", "*.egg-info")
            shutil.copytree(source, tree / name, symlinks=True, ignore=ignore)
        else:
            shutil.copy2(source, tree / name)
    out = tmp_path_factory.mktemp("dist")
    cmd = [sys.executable, "-m", "pip", "wheel", str(tree), "--no-deps", "--no-build-isolation"]
    subprocess.run([*cmd, "-q", "-w", str(out)], check=True, capture_output=True, timeout=120)
    [built] = out.glob("assistantx-*.whl")
    return built


def test_the_wheel_carries_copies_of_the_canonical_files(wheel: Path) -> None:
    with zipfile.ZipFile(wheel) as archive:
        for name in CANONICAL:
            packed = archive.read(f"assistantx/data/{name}")
            assert packed == (ROOT / name).read_bytes(), name
        assert "assistantx/static/index.html" in archive.namelist()


def test_an_installed_package_finds_its_data_from_elsewhere(wheel: Path, tmp_path: Path) -> None:
    site = tmp_path / "site"
    with zipfile.ZipFile(wheel) as archive:
        archive.extractall(site)  # what pip install puts into site-packages
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    # The unpacked wheel comes first on the path, ahead of the checkout's editable install.
    env = {"PYTHONPATH": str(site), "PATH": "/usr/bin:/bin"}
    done = subprocess.run(
        [sys.executable, "-c", PROBE],
        cwd=elsewhere,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    found = json.loads(done.stdout)
    assert Path(found["package"]).is_relative_to(site)
    assert all(Path(p).is_relative_to(site) and Path(p).exists() for p in found["paths"])
    assert found["people"] > 10 and found["metres"] > 5
    assert {"decision.md", "perception.md", "planning.md", "reflection.md"} <= set(found["prompts"])
