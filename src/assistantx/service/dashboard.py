"""The web dashboard's own routes, beyond the REST API (the page itself is ``static/``,
served at ``/`` by the app).

- ``GET /v1/map``: the occupancy map's metadata (resolution, origin, size in cells) and the
  anchors of the office's places with their names, so the page can turn world metres into
  pixels of ``GET /v1/map.png``: ``px = (x - origin_x) / resolution`` and
  ``py = height - (y - origin_y) / resolution`` (the image's top row is the map's last row).
- ``GET /v1/map.png``: the map rendered one pixel per cell (free white, occupied black,
  unknown grey, as map_server shows them).
- ``GET /v1/evaluation/latest``: the newest evaluation run under ``settings.results_dir``
  (its ``summary.json``, ``summary.md`` and the URLs of its charts), and
  ``GET /v1/evaluation/runs/{run}/{file}`` to fetch one of those files.
- ``GET /v1/locker/codes``, ``POST /v1/locker/scan`` and ``POST /v1/locker/close``: the QR
  codes recent instructions issued, and the operator acting as the person at the locker
  (scan a code, shut the door), so a demo with human colleagues can finish a hand-over.

Every route needs a token (the page asks for one); the locker's are for the operator only.
"""

from __future__ import annotations

import functools
import io
import json
import logging
import re
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
from fastapi import APIRouter, Request, Response
from fastapi.responses import FileResponse
from pydantic import BaseModel, ConfigDict, Field

from assistantx.core.errors import MapError
from assistantx.core.office import Office
from assistantx.core.ports.lock import LockEvent
from assistantx.core.wording import person_name, purpose_text
from assistantx.memory.short_term import CodeState
from assistantx.nav.anchors import Anchor, load_anchors
from assistantx.nav.occupancy_map import OccupancyMap, load_map
from assistantx.service.codebook import CodeBook
from assistantx.service.deps import Caller, Runtime
from assistantx.service.errors import ConflictError, NotFoundError, UnavailableError
from assistantx.service.robots import desk_for_code, open_desk
from assistantx.service.runtime import ServiceRuntime

logger = logging.getLogger(__name__)

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
    def from_files(
        cls, map_yaml: Path, office: Office, anchors_yaml: Path | None = None
    ) -> OfficeMap:
        anchors_path = anchors_yaml or map_yaml.with_name(map_yaml.stem + ".anchors.yaml")
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
        raise UnavailableError(
            f"evaluation run {run.name}: cannot read summary.json: {exc}"
        ) from exc
    if not isinstance(summary, dict | list):
        raise UnavailableError(f"evaluation run {run.name}: summary.json is not an object")
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


# -- codes in people's hands (for the simulated scan) ----------------------------------------
class LockerCode(BaseModel):
    code_id: str
    instruction_id: str
    person: str
    item: str
    purpose: str
    person_name: str = Field(description="the holder's display name")
    task: str = Field(description="what the holder does at the locker, in words")
    used: bool = Field(description="the instruction saw it used at the locker")
    state: CodeState = Field(
        description="issued (still opens the locker), scanned (the door opened), used (the "
        "door closed after it) or revoked (withdrawn: hand-over timed out, instruction ended)"
    )
    scannable: bool = Field(description="the dashboard knows the code's payload")


class ScanIn(BaseModel):
    model_config = ConfigDict(extra="forbid")
    code_id: str = Field(min_length=1, max_length=100)


def _codebook(runtime: ServiceRuntime) -> CodeBook:
    for held in runtime.sim.codes:  # simulated people's codes (restored after a restart)
        if held.payload:
            runtime.codebook.add(held.payload)
    return runtime.codebook


def _recent_codes(runtime: ServiceRuntime, book: CodeBook, limit: int = 30) -> list[LockerCode]:
    codes: list[LockerCode] = []
    for record in runtime.journal.instructions(limit=limit):
        stm = runtime.assistant.get(record.id)
        if stm is None:
            full = runtime.journal.instruction(record.id)
            stm = full.stm if full else None
        if stm is None:
            continue
        codes.extend(
            LockerCode(
                code_id=c.code_id,
                instruction_id=record.id,
                person=c.person,
                item=c.item,
                purpose=c.purpose,
                person_name=person_name(runtime.office, c.person),
                task=purpose_text(runtime.office, c.purpose, c.item),
                used=c.used,
                state=c.current_state(runtime.locker.code_states),
                scannable=book.payload(c.code_id) is not None,
            )
            for c in stm.embodied.codes
        )
    return codes


# -- the router ------------------------------------------------------------------------------
router = APIRouter(prefix="/v1", tags=["dashboard"])


def _office_map(request: Request, runtime: ServiceRuntime) -> OfficeMap:
    """Loaded on first use, so a missing map file costs the map view, not the start-up."""
    maps: dict[str, OfficeMap] | None = getattr(request.app.state, "dashboard_maps", None)
    if maps is None:
        maps = request.app.state.dashboard_maps = {}
    key = str(runtime.settings.data_dir)  # one map per office
    cached = maps.get(key)
    if cached is None:
        try:
            cached = OfficeMap.from_files(
                runtime.map_yaml, runtime.office, runtime.settings.map_anchors
            )
        except MapError as exc:
            logger.warning("dashboard map unavailable: %s", exc)
            raise UnavailableError(f"the office map cannot be loaded: {exc}") from exc
        maps[key] = cached
    return cached


@router.get("/map", response_model=MapInfo, summary="The office map's metadata and anchors")
async def map_info(request: Request, runtime: Runtime, caller: Caller) -> MapInfo:
    return _office_map(request, runtime).info


@router.get(
    "/map.png",
    response_class=Response,
    responses={200: {"content": {"image/png": {}}}},
    summary="The office map as a PNG, one pixel per cell",
)
async def map_png(request: Request, runtime: Runtime, caller: Caller) -> Response:
    png = _office_map(request, runtime).png
    return Response(png, media_type="image/png", headers={"Cache-Control": "max-age=3600"})


@router.get(
    "/evaluation/latest",
    response_model=EvaluationRun,
    summary="The newest evaluation run's summary and chart URLs",
)
async def evaluation_latest(runtime: Runtime, caller: Caller) -> EvaluationRun:
    results_dir = runtime.settings.results_dir
    run = latest_run(results_dir)
    if run is None:
        raise NotFoundError(f"no evaluation run with a summary.json in {results_dir}")
    return read_run(run)


@router.get(
    "/evaluation/runs/{run}/{name}",
    response_class=FileResponse,
    summary="One file (chart, summary) of an evaluation run",
)
async def evaluation_file(run: str, name: str, runtime: Runtime, caller: Caller) -> FileResponse:
    media_type = _RUN_FILES.get(Path(name).suffix)
    if not (_SAFE_NAME.match(run) and _SAFE_NAME.match(name)) or media_type is None:
        raise NotFoundError("unknown evaluation file (plain names only; .png, .json or .md)")
    path = runtime.settings.results_dir / run / name
    if not path.is_file():
        raise NotFoundError(f"evaluation run {run!r} has no file {name!r}")
    return FileResponse(path, media_type=media_type)


@router.get(
    "/locker/codes",
    response_model=list[LockerCode],
    summary="QR codes issued by recent instructions, newest instruction first",
)
async def locker_codes(request: Request, runtime: Runtime, caller: Caller) -> list[LockerCode]:
    caller.require_operator()
    return _recent_codes(runtime, _codebook(runtime))


@router.post(
    "/locker/scan",
    response_model=LockEvent,
    summary="Simulate a person scanning a code at the locker (operator only)",
)
async def locker_scan(
    body: ScanIn, request: Request, runtime: Runtime, caller: Caller
) -> LockEvent:
    """Holds the code's QR payload up to the scanner: answers ``code_accepted`` (the door
    opens) or ``code_rejected`` with the lock's reason (used, expired, door open, ...)."""
    caller.require_operator()
    payload = _codebook(runtime).payload(body.code_id)
    if payload is None:
        raise NotFoundError(
            f"no QR code {body.code_id!r} is known to the dashboard (it notes codes sent "
            "while the service runs, and those simulated colleagues hold)"
        )
    desk = await desk_for_code(runtime, body.code_id)  # the robot that carries it
    event = await desk.simulate_scan(payload)
    logger.info("dashboard: simulated scan of %s: %s", body.code_id, event.kind)
    return event


@router.post(
    "/locker/close",
    response_model=LockEvent,
    summary="Simulate the person shutting the locker's door (operator only)",
)
async def locker_close(runtime: Runtime, caller: Caller) -> LockEvent:
    caller.require_operator()
    desk = await open_desk(runtime)
    if desk is None:
        raise ConflictError("the locker's door is already closed")
    return await desk.simulate_close()
