"""The served process keeps at most two glibc malloc arenas (issue 26: resident memory flat
over 10,000 instructions). Counted by glibc itself: ``malloc_info`` writes one ``<heap>`` per
arena, in a fresh interpreter whose threads each allocate."""

from __future__ import annotations

import os
import platform
import subprocess
import sys
import textwrap

import pytest

from assistantx.service.malloc_arenas import limit_arenas

glibc_only = pytest.mark.skipif(
    platform.libc_ver()[0] != "glibc", reason="malloc arenas are glibc's"
)

# Eight threads allocate blocks too big for Python's own allocator (served by malloc), all
# alive at once; then glibc's malloc_info is written to a file and its arenas counted.
_PROGRAM = textwrap.dedent(
    """
    import ctypes, sys, tempfile, threading
    from assistantx.service.malloc_arenas import limit_arenas
    print("limited" if sys.argv[1] == "limit" and limit_arenas() else "as is")
    start, done = threading.Barrier(9), threading.Barrier(9)
    def work():
        start.wait()
        blocks = [bytearray(4096) for _ in range(200)]
        done.wait()
        del blocks
    threads = [threading.Thread(target=work) for _ in range(8)]
    for t in threads:
        t.start()
    start.wait()
    done.wait()
    for t in threads:
        t.join()
    libc = ctypes.CDLL(None)
    libc.fopen.restype = ctypes.c_void_p
    libc.fopen.argtypes = [ctypes.c_char_p, ctypes.c_char_p]
    libc.malloc_info.argtypes = [ctypes.c_int, ctypes.c_void_p]
    libc.fclose.argtypes = [ctypes.c_void_p]
    with tempfile.NamedTemporaryFile(suffix=".xml") as out:
        f = libc.fopen(out.name.encode(), b"w")
        libc.malloc_info(0, f)
        libc.fclose(f)
        print(open(out.name).read().count("<heap nr="))
    """
)


def _arenas(mode: str, **env: str) -> tuple[str, int]:
    environ = {k: v for k, v in os.environ.items() if k != "MALLOC_ARENA_MAX"} | env
    done = subprocess.run(
        [sys.executable, "-c", _PROGRAM, mode],
        capture_output=True,
        text=True,
        check=True,
        timeout=60,
        env=environ,
    )
    said, count = done.stdout.splitlines()
    return said, int(count)


@glibc_only
def test_limited_threads_share_two_arenas_where_unlimited_ones_take_more() -> None:
    assert _arenas("limit") == ("limited", 2)
    said, count = _arenas("as-is")
    assert said == "as is" and count > 2


@glibc_only
def test_an_operators_own_malloc_arena_max_is_left_as_it_is() -> None:
    assert _arenas("limit", MALLOC_ARENA_MAX="4") == ("as is", 4)


def test_a_count_below_one_is_refused() -> None:
    with pytest.raises(ValueError, match="at least 1"):
        limit_arenas(0)
