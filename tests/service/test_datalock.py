"""The data folder's lock: its file is ``assistantx.lock``, and a folder that still has the
file of the release that named it ``assistantx.adapters.lock.protocol`` (a package rename
rewrote the string) is held under both names, so a process of that release and one of this
release never serve from one folder during an upgrade. ``flock`` locks belong to an open
file, so two locks in one process contend as two processes would."""

from __future__ import annotations

import fcntl
import os
from pathlib import Path

import pytest

from assistantx.service.datalock import OLD_LOCK_FILE, DataDirBusyError, DataDirLock


def test_the_lock_file_is_named_for_what_it_is(tmp_path: Path) -> None:
    lock = DataDirLock(tmp_path).acquire()
    try:
        assert sorted(p.name for p in tmp_path.iterdir()) == ["assistantx.lock"]
        assert (tmp_path / "assistantx.lock").read_text() == f"{os.getpid()}\n"
        with pytest.raises(DataDirBusyError, match="another assistantx process"):
            DataDirLock(tmp_path).acquire()
    finally:
        lock.release()
    DataDirLock(tmp_path).acquire().release()  # free again once released


def test_a_process_of_the_old_release_holding_the_old_file_keeps_the_folder(
    tmp_path: Path,
) -> None:
    old = tmp_path / OLD_LOCK_FILE
    fd = os.open(old, os.O_RDWR | os.O_CREAT, 0o600)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)  # what the old release's serve holds
        with pytest.raises(DataDirBusyError):
            DataDirLock(tmp_path).acquire()
        # refused without keeping the new name's lock: the old process may stop and we retry
        fcntl.flock(fd, fcntl.LOCK_UN)
        lock = DataDirLock(tmp_path).acquire()
    finally:
        os.close(fd)
    try:
        probe = os.open(old, os.O_RDWR)
        try:  # the old name is held by this release too while its file is there
            with pytest.raises(BlockingIOError):
                fcntl.flock(probe, fcntl.LOCK_EX | fcntl.LOCK_NB)
        finally:
            os.close(probe)
    finally:
        lock.release()
