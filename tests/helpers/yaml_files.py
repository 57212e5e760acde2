"""A YAML file's document for the tests that edit an office's (or another data file's) raw
form before parsing it: read with libyaml's loader (what ``core.yaml_file.read_yaml``, the
office loader, uses) and parsed once per file content, each caller getting its own deep copy
to edit. The pure-Python ``yaml.safe_load`` took ~40 ms for the default office and the
tests read it ~100 times."""

from __future__ import annotations

import copy
import functools
from pathlib import Path
from typing import Any

import yaml


def raw_yaml(path: Path) -> Any:
    """The document in ``path``, a fresh copy the caller may change (the parse is kept by the
    file's text, so an edited file is read again)."""
    return copy.deepcopy(_parsed(path.read_text(encoding="utf-8")))


@functools.cache
def _parsed(text: str) -> Any:
    return yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
