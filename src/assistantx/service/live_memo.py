"""Values remembered for the keys of the last call only: a cache that holds what is live.

The simulated world's snapshot is built at every checkpoint, and most of what it names is as
it was at the one before (the codes in people's hands). An LRU cache of every code ever seen
kept thousands of ended codes' records and grew for most of a 10,000-instruction run (issue
26's resident-memory target); this one keeps exactly the keys asked for last time, so its
size follows the codes held now, and an unchanged key still costs a lookup, not a rebuild.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable
from typing import Generic, TypeVar

K = TypeVar("K", bound=Hashable)
V = TypeVar("V")


class LiveMemo(Generic[K, V]):
    """``make(key)`` for each key, reusing the values of the previous call's keys; what the
    previous call had and this one has not is forgotten."""

    def __init__(self, make: Callable[[K], V]) -> None:
        self._make = make
        self._kept: dict[K, V] = {}

    def values(self, keys: Iterable[K]) -> list[V]:
        kept = self._kept
        now: dict[K, V] = {}
        out: list[V] = []
        for key in keys:
            if key in now:
                value = now[key]
            elif key in kept:
                value = kept[key]
            else:
                value = self._make(key)
            now[key] = value
            out.append(value)
        self._kept = now
        return out

    def __len__(self) -> int:
        return len(self._kept)
