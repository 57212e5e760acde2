"""One service per data folder: an exclusive ``flock`` on a file in it.

Two processes on one journal would both resume the running instructions (duplicate steps and
messages), so ``assistantx serve`` takes this lock first, before it binds its port and before
anything is read from the journal; the lock goes with the process (the kernel drops it when
the descriptor closes, also after ``kill -9``).
"""

from __future__ import annotations

import fcntl
import os
from pathlib import Path

from assistantx.core.errors import AssistantXError

LOCK_FILE = "assistantx.adapters.lock.protocol"


class DataDirBusyError(AssistantXError):
    """Another process serves from this data folder."""


class DataDirLock:
    """Held from ``acquire()`` until ``release()`` (or the end of the process)."""

    def __init__(self, data_dir: Path) -> None:
        self.path = data_dir / LOCK_FILE
        self._fd: int | None = None

    @property
    def held(self) -> bool:
        return self._fd is not None

    def acquire(self) -> DataDirLock:
        self.path.parent.mkdir(parents=True, exist_ok=True)
        fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o600)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise DataDirBusyError(
                f"another assistantx process is serving from the data folder {self.path.parent}"
                " (stop it first, or set ASSISTANTX_DATA_DIR to another folder)"
            ) from None
        # The holder's pid, for a person looking at the folder; the lock itself is the flock.
        os.ftruncate(fd, 0)
        os.write(fd, f"{os.getpid()}\n".encode())
        self._fd = fd
        return self

    def release(self) -> None:
        if self._fd is not None:
            fcntl.flock(self._fd, fcntl.LOCK_UN)
            os.close(self._fd)
            self._fd = None
