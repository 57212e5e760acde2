"""Reading a YAML file the way the loaders of office, base-instruction and deployment files
do: a file that cannot be read, or that is not YAML, is a problem the caller reports in its
own error naming the file."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import yaml


def read_yaml(path: Path, problem: Callable[[str], Exception]) -> Any:
    """The YAML document in ``path``; ``problem(why)`` is raised when the file cannot be read
    or is not YAML (``why``: "cannot be read: …", "is not valid YAML: …")."""
    try:
        # libyaml's loader when present: the pure-Python one takes seconds on a large office.
        loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
        return yaml.load(path.read_text(encoding="utf-8"), Loader=loader)
    except OSError as exc:
        raise problem(f"cannot be read: {exc.strerror or exc}") from exc
    except yaml.YAMLError as exc:
        raise problem(f"is not valid YAML: {exc}") from exc
