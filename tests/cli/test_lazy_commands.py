"""Each command imports what it uses: a command named on the command line imports its own
module, not every command's (``office show`` used to load FastAPI, SciPy and Matplotlib
through ``lock_cmd``). Checked in a fresh interpreter, by what ``sys.modules`` holds."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow

HEAVY = ("fastapi", "uvicorn", "scipy", "matplotlib")
MAPS = Path(__file__).resolve().parents[2] / "maps"

# Runs the CLI's own entry point in a fresh interpreter, then prints which heavy packages it
# imported (to stderr, after the command's output, so the two do not mix).
_PROBE = """
import json, sys
from assistantx.cli import main
try:
    code = main(sys.argv[1:])
except SystemExit as exc:
    code = exc.code
heavy = sorted(m for m in {heavy!r} if m in sys.modules)
print(json.dumps({{"code": code, "heavy": heavy}}), file=sys.stderr)
"""


def _heavy_imports(*argv: str) -> tuple[object, list[str], str]:
    out = subprocess.run(
        [sys.executable, "-c", _PROBE.format(heavy=HEAVY), *argv],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    report = json.loads(out.stderr.strip().splitlines()[-1])
    return report["code"], report["heavy"], out.stdout


def test_office_show_imports_no_web_or_plotting_library() -> None:
    code, heavy, stdout = _heavy_imports("office", "show")
    assert code == 0
    assert "What the assistant knows at start:" in stdout
    assert heavy == []


@pytest.mark.parametrize("command", ["run", "lock-keys"])
def test_commands_that_serve_nothing_import_no_web_framework(command: str) -> None:
    code, heavy, _ = _heavy_imports(command, "--help")
    assert code == 0
    assert "fastapi" not in heavy and "uvicorn" not in heavy


def test_a_mistyped_command_still_lists_every_command() -> None:
    out = subprocess.run(
        [sys.executable, "-m", "assistantx", "ofice", "show"],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert out.returncode == 2
    for command in ("office", "run", "serve", "lock-keys", "report", "matrix"):
        assert command in out.stderr


# What `serve` imports before it is ready: the app and the server. The reader (a third of a
# start, mostly lemminflect's tables) loads after ready (the reasoner's warm-up) or on the
# first consent check.
_SERVE_PROBE = """
import json, sys
import assistantx.cli.serve_cmd, assistantx.service.app, assistantx.service.server
print(json.dumps(sorted(m for m in {late!r} if m in sys.modules)))
"""
LOADED_AFTER_READY = (
    "assistantx.agents.symbolic.reading.parser",
    "assistantx.agents.symbolic.reading.frames",  # reads lemminflect's tables as it loads
)


def test_the_service_imports_no_reader_before_it_is_ready() -> None:
    out = subprocess.run(
        [sys.executable, "-c", _SERVE_PROBE.format(late=LOADED_AFTER_READY)],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    assert json.loads(out.stdout.strip().splitlines()[-1]) == []


# The embedded service journals to SQLite: PostgreSQL's driver is for replicas on a shared
# database (ASSISTANTX_DATABASE_URL) and is imported where they connect.
ONLY_WITH_A_DATABASE = ("psycopg", "psycopg_binary", "psycopg_c", "psycopg_pool")


def test_the_service_imports_no_postgres_driver_without_a_database() -> None:
    out = subprocess.run(
        [sys.executable, "-c", _SERVE_PROBE.format(late=ONLY_WITH_A_DATABASE)],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    assert json.loads(out.stdout.strip().splitlines()[-1]) == []


# What `serve` does with the map before ready (serve_cmd keeps the map's arrays in the data
# folder's map cache; the runtime builds the navigator, localizing), in a fresh interpreter.
# Prints whether scipy was imported and the cache's files with their modification times.
_MAP_CACHE_PROBE = """
import json, sys
from pathlib import Path
from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.clock import SimClock
from assistantx.core.office import load_office
from assistantx.nav import disk_cache

cache = Path(sys.argv[1])
disk_cache.use_directory(cache)
NavigatorRobot.from_files(load_office(), SimClock(), map_yaml=sys.argv[2], localize=True)
files = {{f.name: f.stat().st_mtime_ns for f in cache.iterdir()}}
print(json.dumps({{"scipy": "scipy" in sys.modules, "files": files}}))
"""
CACHED_KINDS = {
    "obstacle-distance",
    "inflation-costs",
    "endpoint-distance",
    "endpoint-log-likelihood",
    "traversable-components",
}


def _start_on(cache: Path, map_yaml: Path) -> tuple[bool, dict[str, int]]:
    out = subprocess.run(
        [sys.executable, "-c", _MAP_CACHE_PROBE.format(), str(cache), str(map_yaml)],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    report = json.loads(out.stdout.strip().splitlines()[-1])
    return report["scipy"], report["files"]


def _office_map_copy(folder: Path) -> Path:
    folder.mkdir()
    for name in ("office.yaml", "office.pgm", "office.anchors.yaml"):
        shutil.copy(MAPS / name, folder / name)
    return folder / "office.yaml"


def test_a_first_start_computes_the_map_cache_without_scipy_and_a_second_reads_it(
    tmp_path: Path,
) -> None:
    cache, map_yaml = tmp_path / "map-cache", _office_map_copy(tmp_path / "maps")
    used_scipy, first = _start_on(cache, map_yaml)
    assert not used_scipy  # its import was a quarter of a CPU-second of a first start
    assert {name.rsplit("-", 1)[0] for name in first} == CACHED_KINDS
    used_scipy, second = _start_on(cache, map_yaml)
    assert not used_scipy
    assert second == first  # the same files, not one written again: read


def test_an_edited_map_gets_arrays_of_its_own(tmp_path: Path) -> None:
    cache, map_yaml = tmp_path / "map-cache", _office_map_copy(tmp_path / "maps")
    _, before = _start_on(cache, map_yaml)
    pgm = map_yaml.with_suffix(".pgm")
    pixels = bytearray(pgm.read_bytes())
    free = pixels.index(254, len(pixels) // 2)  # a white pixel halfway down the map
    pixels[free] = 0  # now black: an occupied cell
    pgm.write_bytes(bytes(pixels))
    _, after = _start_on(cache, map_yaml)
    for kind in CACHED_KINDS:
        assert len([name for name in after if name.startswith(kind)]) == 2, kind
    assert {name: after[name] for name in before} == before  # the old map's, untouched
