"""The service's data folder: where it is made, and the names of the files kept in it.

A module of its own (no FastAPI, no adapters) so that ``lock-keys`` and ``lock-sim`` can find
the same folder as ``serve`` without importing the whole service.
"""

from __future__ import annotations

import os
from pathlib import Path

LOCK_KEYS_FILE = "lock-keys.json"


def ensure_data_dir(path: Path) -> Path:
    """The data folder, made owner-only (it holds the journal and the lock's keys)."""
    path.mkdir(parents=True, exist_ok=True)
    os.chmod(path, 0o700)
    return path
