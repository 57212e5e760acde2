"""Exponential backoff with full jitter: the one rule for how long every retry waits.

Retry number ``attempt`` (0 for the first) waits a uniform draw from ``[min_s, ceiling]``
where ``ceiling = min(max_s, initial_s * factor**attempt)``. With the default ``min_s = 0``
that is "full jitter" (AWS Architecture Blog, "Exponential Backoff And Jitter", 2015): of the
usual schemes it spreads many clients retrying after the same outage the most, so they do
not come back in step. ``min_s`` is a floor for a caller that must not come back sooner.

The draw comes from a ``random.Random`` the caller owns and passes in, never the module-level
generator: a seeded one makes a run's delays reproducible, and nothing else's draws shift them.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

_MAX_EXPONENT = 64  # far past any cap; keeps factor**attempt a float, not an overflow


@dataclass(frozen=True)
class Backoff:
    """Delays in seconds: ``initial_s * factor**attempt`` capped at ``max_s``, full jitter."""

    initial_s: float = 0.1
    max_s: float = 10.0
    factor: float = 2.0
    min_s: float = 0.0

    def __post_init__(self) -> None:
        if min(self.initial_s, self.max_s, self.min_s) < 0:
            raise ValueError("backoff delays must be >= 0")
        if self.factor < 1:
            raise ValueError("the backoff factor must be >= 1")
        if self.min_s > self.max_s:
            raise ValueError("the backoff floor min_s exceeds its cap max_s")

    def ceiling_s(self, attempt: int) -> float:
        """The longest wait before retry number ``attempt``."""
        grown = self.initial_s * self.factor ** min(max(attempt, 0), _MAX_EXPONENT)
        return max(self.min_s, min(self.max_s, grown))

    def delay_s(self, attempt: int, rng: random.Random) -> float:
        """The wait before retry number ``attempt``, drawn from ``rng``."""
        return rng.uniform(self.min_s, self.ceiling_s(attempt))
