from pathlib import Path

import yaml

from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml


def _safe_loaded(path: Path) -> object:
    return yaml.safe_load(path.read_text(encoding="utf-8"))


def test_the_cached_document_is_the_safe_loaders_and_each_caller_gets_its_own_copy() -> None:
    for path in (DEFAULT_FILE, HARBOUR_FILE):
        assert raw_yaml(path) == _safe_loaded(path)
    first = raw_yaml(DEFAULT_FILE)
    first["people"].clear()
    first["name"] = "changed"
    assert raw_yaml(DEFAULT_FILE) == _safe_loaded(DEFAULT_FILE)


def test_an_edited_file_is_read_again(tmp_path: Path) -> None:
    file = tmp_path / "x.yaml"
    file.write_text("a: 1\n", encoding="utf-8")
    assert raw_yaml(file) == {"a": 1}
    file.write_text("a: 2\n", encoding="utf-8")
    assert raw_yaml(file) == {"a": 2}
