"""``assistantx map render`` writes a PNG of the map, anchors, path and particles."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import numpy.typing as npt
import pytest

from assistantx.cli import main
from assistantx.nav.anchors import Anchor, load_anchors, save_anchors
from assistantx.nav.costmap import Costmap
from assistantx.nav.occupancy_map import load_map
from assistantx.nav.planner import GridPlanner
from helpers.children import descendants
from helpers.maps import REPO, real_map


def _read_png(path: Path) -> npt.NDArray[np.float32]:
    # matplotlib is imported by the tests that read a picture, not at collection: about a
    # CPU-second in every xdist worker otherwise
    import matplotlib.image as mpimg

    image: npt.NDArray[np.float32] = mpimg.imread(path)
    return image


def test_render_with_path_and_particles(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "office.png"
    running = {child.pid for child in descendants(os.getpid())}
    code = main(["map", "render", "--out", str(out), "--path", "desk_01,desk_02", "--particles"])
    assert code == 0
    # One plan and one drive: planned in this process, no planning worker started for it.
    assert [c for c in descendants(os.getpid()) if c.pid not in running] == []
    assert "path 4.00 m" in capsys.readouterr().out
    image = _read_png(out)
    assert image.shape[0] > 300
    assert image.shape[1] > 500
    # Blue path, red particles and green anchors are drawn on the grey map.
    rgb = image[..., :3]
    assert np.any((rgb[..., 2] > 0.6) & (rgb[..., 0] < 0.3))
    assert np.any((rgb[..., 0] > 0.7) & (rgb[..., 1] < 0.4) & (rgb[..., 2] < 0.4))


def test_render_errors(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "x.png"
    assert main(["map", "render", "--out", str(out), "--path", "desk_01"]) == 2
    assert main(["map", "render", "--out", str(out), "--path", "desk_01,attic"]) == 1
    assert (
        capsys.readouterr()
        .out.splitlines()[1]
        .startswith("error: Unknown place 'attic'. Use a person's name")
    )
    assert main(["map", "render", "--out", str(out), "--map", str(tmp_path / "no.yaml")]) == 1
    assert not out.exists()


def test_render_a_real_map_without_anchors(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "depot.png"
    assert main(["map", "render", "--out", str(out), "--map", str(real_map("depot"))]) == 0
    assert "(no anchors)" in capsys.readouterr().out
    assert _read_png(out).shape[1] > 300


def test_check_names_file_location_and_problem(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    anchors = load_anchors(REPO / "maps" / "office.anchors.yaml")
    anchors["kitchenette"] = Anchor(29.0, 24.0, 0.0)  # inside the counter
    del anchors["desk_05"]
    bad = tmp_path / "bad.anchors.yaml"
    save_anchors(anchors, bad)
    code = main(["map", "check", "--anchors", str(bad)])
    lines = capsys.readouterr().out.splitlines()
    assert code == 1
    assert lines == [
        f"{bad}: location 'desk_05' has no anchor",
        f"{bad}: location 'kitchenette': (29.00, 24.00) is inside an obstacle",
    ]
    assert main(["map", "check"]) == 0
    assert "all in free space and reachable" in capsys.readouterr().out


def test_serve_refuses_a_bad_anchor_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    anchors = load_anchors(REPO / "maps" / "office.anchors.yaml")
    anchors["print_room"] = Anchor(-50.0, 3.0, 0.0)
    bad = tmp_path / "bad.anchors.yaml"
    save_anchors(anchors, bad)
    monkeypatch.setenv("ASSISTANTX_DATA_DIR", str(tmp_path / "data"))
    monkeypatch.setenv("ASSISTANTX_MAP_ANCHORS", str(bad))
    assert main(["serve", "--port", "1"]) == 2
    out = capsys.readouterr().out.strip().splitlines()
    assert out == [f"error: {bad}: anchor 'print_room': (-50.00, 3.00) is off the map"]


@pytest.mark.parametrize(
    "path", ["Lee,Print_Room", "Desk 3,Print room", "lee ming,print room", "desk_03,print_room"]
)
def test_render_takes_places_as_every_command_names_them(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], path: str
) -> None:
    # Lee's desk is desk_03: a person, a location's name in any case or its id are one place.
    # The length is the smoothed path's from desk_03's anchor to the print room's.
    anchors = load_anchors(REPO / "maps" / "office.anchors.yaml")
    start, goal = anchors["desk_03"], anchors["print_room"]
    planner = GridPlanner(Costmap.inflate(load_map(REPO / "maps" / "office.yaml")))
    metres = planner.plan((start.x, start.y), (goal.x, goal.y)).length_m
    out = tmp_path / "path.png"
    assert main(["map", "render", "--out", str(out), "--path", path]) == 0
    assert capsys.readouterr().out == f"wrote {out}, path {metres:.2f} m\n"
