"""tests/ mirrors src/assistantx/: every folder of tests that holds Python files is named after
a package or a module of the source (``tests/store/sqlite_store/`` tests
``store/sqlite_store.py``), so the tests of a module are found where the module is. The only
other folders are the suites run apart under their own marker and the helpers they share."""

from __future__ import annotations

from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
SRC = TESTS.parent / "src" / "assistantx"

# Folders with no source counterpart, each with the reason it stands apart.
NOT_MIRRORED = {
    "browser": "marker suite: drives Chromium through the service's web pages",
    "synapse": "marker suite: a real Synapse homeserver and Matrix clients of people",
    "llm_server": "marker suite: llama.cpp's server with a real small model",
    "helpers": "helpers shared by every folder (servers, waiting, offices, lock fixtures)",
    "fakes": "the scripted OpenAI-compatible model server, a fake of the outside world",
}


def unmirrored(tests: Path, src: Path, allowed: dict[str, str]) -> list[str]:
    """The folders under ``tests`` holding tests (a test module or a conftest) with no package
    or module of the same path under ``src``; a folder of data (prompt files, maps and the
    script that draws them) is a fixture of the tests beside it."""
    found = []
    for folder in sorted(p for p in tests.rglob("*") if p.is_dir()):
        relative = folder.relative_to(tests)
        if relative.parts[0] in allowed or "__pycache__" in relative.parts:
            continue
        if not any(folder.glob("test_*.py")) and not (folder / "conftest.py").is_file():
            continue
        if not ((src / relative).is_dir() or (src / relative).with_suffix(".py").is_file()):
            found.append(relative.as_posix())
    return found


def test_every_test_folder_mirrors_a_source_package_or_module() -> None:
    assert unmirrored(TESTS, SRC, NOT_MIRRORED) == []


def test_the_suites_standing_apart_exist() -> None:
    """An entry for a folder that is gone would let a new folder of that name pass unseen."""
    assert sorted(n for n in NOT_MIRRORED if not (TESTS / n).is_dir()) == []


@pytest.mark.parametrize(
    ("made", "expected"),
    [
        ("memory/test_x.py", []),  # a package
        ("store/sqlite_store/test_x.py", []),  # a module
        ("ppdr/test_x.py", ["ppdr"]),  # the old layout
        ("memory/journal/test_x.py", ["memory/journal"]),  # moved away in src
        ("memory/data/notes.md", []),  # data only
        ("nav/fixtures/make_maps.py", []),  # data and the script that draws it
        ("ppdr/conftest.py", ["ppdr"]),  # fixtures of a folder of the old layout
        ("helpers/deep/test_x.py", []),  # allowed
    ],
)
def test_a_folder_without_a_source_counterpart_is_named(
    tmp_path: Path, made: str, expected: list[str]
) -> None:
    src, tests = tmp_path / "src", tmp_path / "tests"
    (src / "memory").mkdir(parents=True)
    (src / "store").mkdir()
    (src / "store" / "sqlite_store.py").write_text("")
    (tests / made).parent.mkdir(parents=True)
    (tests / made).write_text("")
    assert unmirrored(tests, src, {"helpers": "shared"}) == expected
