"""Office files of the previous format load with the standard services and a warning, and
``assistantx office migrate FILE`` rewrites them in the current format."""

from __future__ import annotations

import logging
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
import yaml

from assistantx.core.office import DEFAULT_OFFICE, load_office, parse_office


def _previous_format() -> dict[str, Any]:
    """The default office as the previous format wrote it: no ``operations:`` block, no item
    type properties, and the microwave beside the fridge where the lunches are kept, with no
    ``facility`` saying which of the two keeps them."""
    raw: dict[str, Any] = yaml.safe_load(DEFAULT_OFFICE.read_text(encoding="utf-8"))
    del raw["operations"]
    for t in raw["item_types"]:
        t.pop("signable", None)
        t.pop("seals", None)
    for f in raw["facilities"]:
        if f["id"] == "microwave":
            f["location"] = "fridge_corner"
    return raw


def test_a_previous_format_office_loads_with_the_standard_services(
    caplog: pytest.LogCaptureFixture,
) -> None:
    with caplog.at_level(logging.WARNING, logger="assistantx.core.office"):
        office = parse_office(_previous_format(), "old.yaml")
    assert {o.id for o in office.operations} == {
        "print",
        "copy",
        "coffee",
        "water",
        "heat",
        "vend",
        "meet",
    }
    assert office.operation("heat").input == "lunch"
    assert office.signable_type() == "document"
    assert office.seal_tool() == "seal"
    # the fridge (no service) keeps the lunches, not the microwave beside it
    keeper = office.keeper("lee", "lunch")
    assert keeper is not None and keeper.id == "fridge"
    said = caplog.text
    assert "old.yaml: previous office format: no 'operations:' block" in said
    assert "kept by 'fridge'" in said


def test_the_current_format_loads_without_a_warning(caplog: pytest.LogCaptureFixture) -> None:
    with caplog.at_level(logging.WARNING, logger="assistantx.core.office"):
        load_office()
    assert caplog.text == ""


@pytest.mark.slow  # starts the CLI as a process: not in `make test-fast`
def test_office_migrate_writes_the_current_format(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    old = tmp_path / "office.yaml"
    old.write_text(yaml.safe_dump(_previous_format(), sort_keys=False), encoding="utf-8")
    out = subprocess.run(
        [sys.executable, "-m", "assistantx", "office", "migrate", str(old)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert out.returncode == 0, out.stdout + out.stderr
    assert f"{old}: updated" in out.stdout
    assert "no 'operations:' block" in out.stdout
    written = yaml.safe_load(old.read_text(encoding="utf-8"))
    assert [o["id"] for o in written["operations"]][:2] == ["print", "copy"]
    with caplog.at_level(logging.WARNING, logger="assistantx.core.office"):
        office = load_office(old)
    assert caplog.text == ""  # nothing left to fill in
    assert office.keeper("zhang", "lunch") == office.facility("fridge")


@pytest.mark.slow  # starts the CLI as a process: not in `make test-fast`
def test_office_migrate_names_a_missing_file(tmp_path: Path) -> None:
    out = subprocess.run(
        [sys.executable, "-m", "assistantx", "office", "migrate", str(tmp_path / "none.yaml")],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert out.returncode == 2
    assert "none.yaml" in out.stdout and "error:" in out.stdout
