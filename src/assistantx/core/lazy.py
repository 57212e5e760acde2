"""Names a package exports from its submodules, imported on first use (PEP 562).

A package's ``__init__`` that imported every submodule would make whoever imports one small
part of it pay for all of it at start-up (the reader's language tools, the model clients).
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Mapping
from typing import Any


def exports(package: str, homes: Mapping[str, str]) -> Callable[[str], Any]:
    """The module ``__getattr__`` of ``package``: each name in ``homes`` is imported from its
    home module (a full dotted name) when first asked for, then kept as a plain attribute."""

    def __getattr__(name: str) -> Any:
        home = homes.get(name)
        if home is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(home), name)
        setattr(sys.modules[package], name, value)  # the next lookup skips this function
        return value

    return __getattr__
