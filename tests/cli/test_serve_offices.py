"""``assistantx serve`` with a deployment of several offices checks the file and every
office's map and anchors before it binds: each problem is one line."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from assistantx.cli import main
from assistantx.nav.anchors import Anchor, load_anchors, save_anchors
from helpers.maps import REPO


def test_serve_refuses_a_bad_anchor_of_the_second_office_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    harbour = REPO / "dataset" / "offices" / "harbour"
    anchors = load_anchors(harbour / "office.anchors.yaml")
    anchors["desk_01"] = Anchor(-50.0, 3.0, 0.0)
    bad = tmp_path / "bad.anchors.yaml"
    save_anchors(anchors, bad)
    deployment = tmp_path / "offices.yaml"
    entries = [
        {"id": "hq", "name": "Headquarters"},
        {"id": "harbour", "office": str(harbour / "office.yaml"), "map_anchors": bad.name},
    ]
    deployment.write_text(yaml.safe_dump({"offices": entries}), encoding="utf-8")
    monkeypatch.setenv("ASSISTANTX_DATA_DIR", str(tmp_path / "data"))
    monkeypatch.setenv("ASSISTANTX_OFFICES", str(deployment))
    assert main(["serve", "--port", "1"]) == 2
    out = capsys.readouterr().out.strip().splitlines()
    assert out == [f"error: {bad}: anchor 'desk_01': (-50.00, 3.00) is off the map"]


def test_serve_refuses_a_bad_deployment_file_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    deployment = tmp_path / "offices.yaml"
    deployment.write_text("offices:\n  - id: hq\n    lock_port: many\n", encoding="utf-8")
    monkeypatch.setenv("ASSISTANTX_DATA_DIR", str(tmp_path / "data"))
    monkeypatch.setenv("ASSISTANTX_OFFICES", str(deployment))
    assert main(["serve", "--port", "1"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"assistantx serve: {deployment}: office 1: ")
    assert "lock_port" in err[0]
