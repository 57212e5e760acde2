"""The import contracts of ``make check`` hold on the source and catch a planted break: an
import of an adapter planted into a package above the ports (in a copy of the source) is
reported as the broken "adapters-from-the-edge" contract, so the contract is not one that
passes whatever the code does."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
LINT_IMPORTS = Path(sys.executable).with_name("lint-imports")
EDGE_CONTRACT = "Only the composition root (service, cli, sim) imports adapters"

pytestmark = pytest.mark.slow


def _copy_of_the_source(tmp_path: Path) -> Path:
    """The package and the import-linter configuration (``pyproject.toml``) in ``tmp_path``."""
    shutil.copytree(
        ROOT / "src" / "assistantx",
        tmp_path / "src" / "assistantx",
        ignore=shutil.ignore_patterns("__pycache__", "data", "static"),
    )
    shutil.copy(ROOT / "pyproject.toml", tmp_path / "pyproject.toml")
    return tmp_path


def _lint_imports(project: Path) -> subprocess.CompletedProcess[str]:
    # The copy comes first on the path: the linter reads the planted module, not ours.
    env = os.environ | {"PYTHONPATH": str(project / "src")}
    return subprocess.run(
        [str(LINT_IMPORTS), "--no-cache"],
        cwd=project,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def _plant(module: Path, line: str) -> None:
    text = module.read_text(encoding="utf-8")
    head, sep, rest = text.partition("from __future__ import annotations\n")
    assert sep, f"{module} has no future import to plant after"
    module.write_text(f"{head}{sep}\n{line}\n{rest}", encoding="utf-8")


def _folded(output: str) -> str:
    """lint-imports wraps long contract names at 80 columns."""
    return " ".join(output.split())


def test_the_copy_of_the_source_keeps_every_contract(tmp_path: Path) -> None:
    result = _lint_imports(_copy_of_the_source(tmp_path))
    assert result.returncode == 0, result.stdout + result.stderr
    assert "0 broken" in result.stdout


@pytest.mark.parametrize(
    ("module", "planted"),
    [
        ("runtime/loop.py", "import assistantx.adapters.robot.navigator"),
        ("feedback/walking.py", "from assistantx.adapters.model import model_from_settings"),
    ],
)
def test_an_adapter_imported_above_the_ports_breaks_the_edge_contract(
    tmp_path: Path, module: str, planted: str
) -> None:
    project = _copy_of_the_source(tmp_path)
    _plant(project / "src" / "assistantx" / module, planted)
    result = _lint_imports(project)
    assert result.returncode != 0
    output = _folded(result.stdout)
    assert f"{_folded(EDGE_CONTRACT)}" in output
    assert "1 broken" in output, output
    dotted = "assistantx." + module.removesuffix(".py").replace("/", ".")
    assert f"{dotted} -> assistantx.adapters" in output, output
