"""Arrays derived from a map, kept on disk by the hash of what they are computed from.

The obstacle distances behind a costmap and AMCL's likelihood field are exact Euclidean
distance transforms of the whole map: most of a robot's set-up on a big floor. They depend
only on the map's cells and a few parameters, so they are stored as ``.npy`` files named by
the SHA-256 of those inputs, and a second start on the same map reads them (an edited map
or other parameters hash differently and are computed afresh; nothing goes stale).

Off until ``use_directory`` names a folder: the service puts it under its data folder; the
library, the tests and the benchmarks compute as before unless they ask for it.

An array asked for ``mapped`` is read as a read-only memory map of its file: a start costs
its header, and the pages are read when first touched (AMCL's field on nav2's warehouse is
two 13 MB arrays a start never reads whole). It is read-only when computed too, so a caller
that writes into it fails on the first start already, not only on a second.
"""

from __future__ import annotations

import hashlib
import logging
import os
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TypeVar

import numpy as np
import numpy.typing as npt

logger = logging.getLogger(__name__)

T = TypeVar("T", bound=np.generic)

FORMAT = "1"  # bump when what a kind of array holds changes: older files are then not read
_directory: Path | None = None


def use_directory(directory: Path | None) -> None:
    """Keep derived arrays in ``directory`` (made if missing); None: keep nothing."""
    global _directory
    if directory is not None:
        directory.mkdir(parents=True, exist_ok=True)
    _directory = directory


def directory() -> Path | None:
    """The folder derived arrays are kept in, None when none."""
    return _directory


def content_key(kind: str, inputs: Iterable[bytes | str | float | int | tuple[int, ...]]) -> str:
    """The hash naming ``kind`` computed from ``inputs`` (arrays passed as their bytes)."""
    digest = hashlib.sha256(f"{kind}\0{FORMAT}".encode())
    for part in inputs:
        digest.update(b"\0")
        digest.update(part if isinstance(part, bytes) else repr(part).encode())
    return digest.hexdigest()[:40]


def cached_array(
    kind: str,
    inputs: Iterable[bytes | str | float | int | tuple[int, ...]],
    compute: Callable[[], npt.NDArray[T]],
    *,
    mapped: bool = False,
) -> npt.NDArray[T]:
    """``compute()``, or the array stored for the same ``kind`` and ``inputs``; ``mapped``:
    read-only, and read from its file as a memory map (see the module's note)."""
    if _directory is None:
        return _read_only(compute()) if mapped else compute()
    file = _directory / f"{kind}-{content_key(kind, inputs)}.npy"
    try:
        # a file shorter than its header says fails here too (ValueError): computed again
        found: npt.NDArray[T] = np.load(file, mmap_mode="r" if mapped else None, allow_pickle=False)
    except FileNotFoundError:
        pass
    except (OSError, ValueError) as exc:  # a torn or foreign file: computed again, replaced
        logger.warning("%s: unreadable cached array (%s); computing it again", file, exc)
    else:
        return found
    value = compute()
    temporary = file.with_name(f".{file.name}.{os.getpid()}.tmp")
    try:
        with temporary.open("wb") as out:
            np.save(out, value, allow_pickle=False)
        os.replace(temporary, file)  # whole or absent: a reader never sees half a file
    except OSError as exc:  # a full or read-only disk costs the next start time, no more
        logger.warning("%s: could not keep the computed array: %s", file, exc)
        temporary.unlink(missing_ok=True)
    return _read_only(value) if mapped else value


def _read_only(value: npt.NDArray[T]) -> npt.NDArray[T]:
    value.flags.writeable = False
    return value
