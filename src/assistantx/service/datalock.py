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

LOCK_FILE = "assistantx.lock"
# The name the lock had for a while (a package rename rewrote the string): a process of that
# release holds this one, so while the file is there it is held too, and the two never share
# a folder during an upgrade.
OLD_LOCK_FILE = "assistantx.adapters.lock.protocol"


class DataDirBusyError(AssistantXError):
    """Another process serves from this data folder."""


class DataDirLock:
    """Held from ``acquire()`` until ``release()`` (or the end of the process)."""

    def __init__(self, data_dir: Path) -> None:
        self.path = data_dir / LOCK_FILE
        self._fds: list[int] = []

    @property
    def held(self) -> bool:
        return bool(self._fds)

    def acquire(self) -> DataDirLock:
        self.path.parent.mkdir(parents=True, exist_ok=True)
        old = self.path.parent / OLD_LOCK_FILE
        try:
            fd = self._lock(self.path, create=True)
            # The holder's pid, for a person looking at the folder; the lock is the flock.
            os.ftruncate(fd, 0)
            os.write(fd, f"{os.getpid()}\n".encode())
            if old.exists():
                self._lock(old, create=False)
        except BaseException:
            self.release()
            raise
        return self

    def _lock(self, path: Path, *, create: bool) -> int:
        fd = os.open(path, os.O_RDWR | (os.O_CREAT if create else 0), 0o600)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise DataDirBusyError(
                f"another assistantx process is serving from the data folder {self.path.parent}"
                " (stop it first, or set ASSISTANTX_DATA_DIR to another folder)"
            ) from None
        self._fds.append(fd)
        return fd

    def release(self) -> None:
        for fd in self._fds:
            fcntl.flock(fd, fcntl.LOCK_UN)
            os.close(fd)
        self._fds = []
