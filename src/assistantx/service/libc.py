"""A function of the process's own C library, by name, for the served process's upkeep of
its heap (``heap_trim``, ``malloc_arenas``): None where the library has no such function
(glibc's ``malloc_trim`` and ``mallopt`` are absent from musl and macOS)."""

from __future__ import annotations

import ctypes
from typing import Any


def libc_function(name: str, argtypes: list[Any], restype: Any) -> Any | None:
    """The C library's ``name`` with its argument and result types set, or None."""
    try:
        libc = ctypes.CDLL(None)
    except OSError:  # pragma: no cover - every POSIX system loads its own C library
        return None
    function = getattr(libc, name, None)
    if function is None:
        return None
    function.argtypes = argtypes
    function.restype = restype
    return function
