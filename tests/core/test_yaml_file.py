"""One reader of YAML files for the office, base-instruction and deployment loaders: the
document, or the caller's own error saying why there is none."""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.core.yaml_file import read_yaml


class _Problem(Exception):
    pass


def test_the_document_is_read(tmp_path: Path) -> None:
    path = tmp_path / "f.yaml"
    path.write_text("offices:\n  - name: harbour\n", encoding="utf-8")
    assert read_yaml(path, _Problem) == {"offices": [{"name": "harbour"}]}


def test_a_missing_file_is_the_callers_problem(tmp_path: Path) -> None:
    with pytest.raises(_Problem, match=r"^cannot be read: No such file or directory$"):
        read_yaml(tmp_path / "missing.yaml", _Problem)


def test_a_file_that_is_not_yaml_is_the_callers_problem(tmp_path: Path) -> None:
    path = tmp_path / "bad.yaml"
    path.write_text("offices: [a\n", encoding="utf-8")
    with pytest.raises(_Problem, match=r"^is not valid YAML: "):
        read_yaml(path, _Problem)
