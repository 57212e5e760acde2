"""At most two glibc malloc arenas in the served process (issue 26).

glibc gives every thread that allocates its own arena, up to eight per core, and each arena
keeps what was freed in it for its own later allocations. The service's threads (the event
loop, the journal's writer, the reasoner's warm-up, the planner's and uvicorn's helpers)
each filled one, and their free memory stayed resident: over ``bench/instructions_10k.py``
(10,000 instructions, 8 in flight) the served process grew 10.9% after the first 1,000,
past the ≤ 10% target, while what Python itself held stayed flat (tracemalloc). With two
arenas, side by side on 4,000 instructions, the growth from 1,000 to 3,000 was 1.7% against
3.7%. The threads still allocate at once: the event loop does almost all of the work, the
others wait on I/O, so they seldom contend for an arena's lock.

Set before the service starts its threads (an arena is chosen at a thread's first
allocation); an operator's own ``MALLOC_ARENA_MAX`` (read by glibc at start) is left as it
is. Where the C library has no ``mallopt`` (musl, macOS) nothing is done.
"""

from __future__ import annotations

import ctypes
import logging
import os

from assistantx.service.libc import libc_function

logger = logging.getLogger(__name__)

ARENAS = 2
M_ARENA_MAX = -8  # glibc's malloc.h


def limit_arenas(count: int = ARENAS) -> bool:
    """glibc's ``mallopt(M_ARENA_MAX, count)``; False where it was not set (the variable
    ``MALLOC_ARENA_MAX`` already says how many, or the C library has no ``mallopt``)."""
    if count < 1:
        raise ValueError("count must be at least 1")
    if "MALLOC_ARENA_MAX" in os.environ:
        return False
    mallopt = libc_function("mallopt", [ctypes.c_int, ctypes.c_int], ctypes.c_int)
    if mallopt is None:
        return False
    done = bool(mallopt(M_ARENA_MAX, count))
    if done:
        logger.debug("at most %d malloc arenas", count)
    return done
