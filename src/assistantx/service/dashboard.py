"""The web dashboard's own routes: the page itself, the office map, and evaluation results.

Everything else the page shows comes from the REST API and the SSE streams. Routes here:

- ``GET /`` the single page (``static/index.html``), ``/static/...`` its scripts and styles;
  both public, since the page asks for a token before it calls the API.
- ``GET /v1/map``: the occupancy map's metadata (resolution, origin, size in cells) and the
  anchors of the office's places with their names, so the page can turn world metres into
  pixels of ``GET /v1/map.png``: ``px = (x - origin_x) / resolution`` and
  ``py = height - (y - origin_y) / resolution`` (the image's top row is the map's last row).
- ``GET /v1/map.png``: the map rendered one pixel per cell (free white, occupied dark,
  unknown grey, as map_server shows them).
- ``GET /v1/evaluation/latest``: the newest evaluation run under ``settings.results_dir``
  (its ``summary.json``, ``summary.md`` and the URLs of its charts), and
  ``GET /v1/evaluation/runs/{run}/{file}`` to fetch one of those files.

The API routes take the caller's dependencies (the service's authentication) so the page
is public while the data is not.
"""

from __future__ import annotations

import functools
import io
import json
import logging
import re
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
from fastapi import APIRouter, HTTPException, Response, params
from fastapi.responses import FileResponse, HTMLResponse
from fastapi.staticfiles import StaticFiles
from pydantic import BaseModel, Field

from assistantx.adapters.robot.navigator import DEFAULT_MAP
from assistantx.errors import MapError
from assistantx.office import Office
from assistantx.robot.anchors import Anchor, load_anchors
from assistantx.robot.occupancy_map import OccupancyMap, load_map

logger = logging.getLogger(__name__)

STATIC_DIR = Path(__file__).resolve().parents[1] / "static"

# Grey levels of map_server's own rendering (free 254, occupied 0, unknown 205).
_FREE_GREY, _UNKNOWN_GREY = 254, 205
# Names of evaluation runs and files the page may fetch: no separators, no dot-dot.
_SAFE_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]{0,127}$")
_RUN_FILES = {".png": "image/png", ".json": "application/json", ".md": "text/markdown"}


# -- the map ---------------------------------------------------------------------------------
class MapAnchor(BaseModel):
    x: float = Field(description="metres, map frame")
    y: float = Field(description="metres, map frame")
    yaw: float = Field(description="radians")
    name: str = Field(description="the place's display name, or the anchor id")
    kind: str = Field(description="workstation, facility, room, or 'anchor' for map-only ones")


class MapInfo(BaseModel):
    """What the page needs to draw world coordinates on ``/v1/map.png``."""

    image: str = Field(description="URL of the PNG, one pixel per cell")
    resolution: float = Field(description="metres per cell (and per PNG pixel)")
    origin: tuple[float, float] = Field(description="world x, y of the lower-left corner, m")
    width: int = Field(description="cells (PNG pixels) along x")
    height: int = Field(description="cells (PNG pixels) along y")
    anchors: dict[str, MapAnchor]


class OfficeMap:
    """The office's occupancy map and anchors, loaded once, with its PNG rendered once."""

    def __init__(self, grid: OccupancyMap, anchors: dict[str, Anchor], office: Office) -> None:
        self.grid = grid
        places = {loc.id: loc for loc in office.locations}
        self.info = MapInfo(
            image="/v1/map.png",
            resolution=grid.resolution,
            origin=(grid.origin_x, grid.origin_y),
            width=grid.width,
            height=grid.height,
            anchors={
                anchor_id: MapAnchor(
                    x=a.x,
                    y=a.y,
                    yaw=a.yaw,
                    name=places[anchor_id].name if anchor_id in places else anchor_id,
                    kind=places[anchor_id].kind if anchor_id in places else "anchor",
                )
                for anchor_id, a in anchors.items()
            },
        )

    @classmethod
    def from_files(cls, map_yaml: Path, office: Office) -> OfficeMap:
        anchors_path = map_yaml.with_name(map_yaml.stem + ".anchors.yaml")
        return cls(load_map(map_yaml), load_anchors(anchors_path), office)

    @functools.cached_property
    def png(self) -> bytes:
        return occupancy_png(self.grid)


def occupancy_grey(data: npt.NDArray[np.int8]) -> npt.NDArray[np.uint8]:
    """Grey levels of occupancy values (0 free … 100 occupied, -1 unknown), rows as given."""
    occupancy = np.clip(data.astype(np.float64), 0, 100) / 100.0
    grey = np.rint(_FREE_GREY * (1.0 - occupancy)).astype(np.uint8)
    grey[data < 0] = _UNKNOWN_GREY
    return grey


def occupancy_png(grid: OccupancyMap) -> bytes:
    """The grid as a greyscale PNG, one pixel per cell, top row = the map's last row."""
    from matplotlib.image import imsave  # imported here: matplotlib is slow to import

    grey = np.flipud(occupancy_grey(grid.data))
    rgb = np.repeat(grey[:, :, np.newaxis], 3, axis=2)
    buffer = io.BytesIO()
    imsave(buffer, rgb, format="png")
    return buffer.getvalue()


# -- evaluation results ----------------------------------------------------------------------
class EvaluationRun(BaseModel):
    run: str = Field(description="the run's folder name under the results directory")
    modified: float = Field(description="when its summary.json was written (Unix time)")
    summary: dict[str, Any] | list[Any] = Field(description="summary.json as written")
    markdown: str | None = Field(default=None, description="summary.md, if written")
    charts: list[str] = Field(default_factory=list, description="URLs of the run's PNG charts")


def latest_run(results_dir: Path) -> Path | None:
    """The run folder whose summary.json is newest (ties broken by name), or None."""
    if not results_dir.is_dir():
        return None
    runs = [
        (summary.stat().st_mtime, run.name, run)
        for run in results_dir.iterdir()
        if run.is_dir()
        and _SAFE_NAME.match(run.name)
        and (summary := run / "summary.json").is_file()
    ]
    return max(runs)[2] if runs else None


def read_run(run: Path) -> EvaluationRun:
    summary_file = run / "summary.json"
    try:
        summary = json.loads(summary_file.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        # A run being written, or a broken one: say which file and why, serve nothing half-read.
        raise HTTPException(
            503, f"evaluation run {run.name}: cannot read summary.json: {exc}"
        ) from exc
    if not isinstance(summary, dict | list):
        raise HTTPException(503, f"evaluation run {run.name}: summary.json is not an object")
    markdown_file = run / "summary.md"
    markdown = markdown_file.read_text(encoding="utf-8") if markdown_file.is_file() else None
    charts = sorted(
        p.name for p in run.iterdir() if p.suffix == ".png" and _SAFE_NAME.match(p.name)
    )
    return EvaluationRun(
        run=run.name,
        modified=summary_file.stat().st_mtime,
        summary=summary,
        markdown=markdown,
        charts=[f"/v1/evaluation/runs/{run.name}/{name}" for name in charts],
    )


# -- the router ------------------------------------------------------------------------------
def dashboard_router(
    office: Office,
    results_dir: Path,
    *,
    map_yaml: Path = DEFAULT_MAP,
    dependencies: Sequence[params.Depends] = (),
) -> APIRouter:
    """The page (public) and its data routes (guarded by ``dependencies``).

    The map is loaded when the first request needs it, so a missing map file costs the
    dashboard its map view (a 503 naming the file), never the service its start-up.
    """
    router = APIRouter()
    api = APIRouter(prefix="/v1", dependencies=list(dependencies), tags=["dashboard"])

    @functools.cache
    def office_map() -> OfficeMap:
        return OfficeMap.from_files(map_yaml, office)

    def loaded_map() -> OfficeMap:
        try:
            return office_map()
        except MapError as exc:
            logger.warning("dashboard map unavailable: %s", exc)
            raise HTTPException(503, f"the office map cannot be loaded: {exc}") from exc

    @router.get("/", include_in_schema=False)
    async def index() -> HTMLResponse:
        return HTMLResponse((STATIC_DIR / "index.html").read_text(encoding="utf-8"))

    @api.get("/map", response_model=MapInfo, summary="The office map's metadata and anchors")
    async def map_info() -> MapInfo:
        return loaded_map().info

    @api.get(
        "/map.png",
        response_class=Response,
        responses={200: {"content": {"image/png": {}}}},
        summary="The office map as a PNG, one pixel per cell",
    )
    async def map_png() -> Response:
        return Response(
            loaded_map().png, media_type="image/png", headers={"Cache-Control": "max-age=3600"}
        )

    @api.get(
        "/evaluation/latest",
        response_model=EvaluationRun,
        summary="The newest evaluation run's summary and chart URLs",
    )
    async def evaluation_latest() -> EvaluationRun:
        run = latest_run(results_dir)
        if run is None:
            raise HTTPException(404, f"no evaluation run with a summary.json in {results_dir}")
        return read_run(run)

    @api.get(
        "/evaluation/runs/{run}/{name}",
        response_class=FileResponse,
        summary="One file (chart, summary) of an evaluation run",
    )
    async def evaluation_file(run: str, name: str) -> FileResponse:
        media_type = _RUN_FILES.get(Path(name).suffix)
        if not (_SAFE_NAME.match(run) and _SAFE_NAME.match(name)) or media_type is None:
            raise HTTPException(
                404, "unknown evaluation file (runs and files are plain names; .png/.json/.md)"
            )
        path = results_dir / run / name
        if not path.is_file():
            raise HTTPException(404, f"evaluation run {run!r} has no file {name!r}")
        return FileResponse(path, media_type=media_type)

    router.include_router(api)
    return router


def mount_static(app: Any) -> None:
    """Serve the page's scripts and styles at ``/static`` (public, no API behind it)."""
    app.mount("/static", StaticFiles(directory=STATIC_DIR), name="static")
