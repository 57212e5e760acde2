"""How many instructions one person may start per minute.

A person who sends forty requests in two seconds (a script, a stuck client, a prank) must not
make the assistant message a colleague forty times. Each person has a sliding one-minute
window of instruction starts, over REST and direct messages alike; beyond the bound a REST
submission is refused with 429 and a direct message is answered in words, once per window.
"""

from __future__ import annotations

import time
from collections import deque
from collections.abc import Callable

WINDOW_S = 60.0


class InstructionRate:
    """``per_minute`` starts per person in any 60 s; 0 means no bound."""

    def __init__(self, per_minute: int, now: Callable[[], float] = time.monotonic) -> None:
        self.per_minute = per_minute
        self._now = now
        self._starts: dict[str, deque[float]] = {}
        self._told: dict[str, float] = {}  # when a person was last told they are over

    def take(self, person: str) -> float | None:
        """Count one start for ``person``; None when allowed, else the seconds until one is."""
        if self.per_minute <= 0:
            return None
        now = self._now()
        starts = self._starts.setdefault(person, deque())
        while starts and starts[0] <= now - WINDOW_S:
            starts.popleft()
        if len(starts) >= self.per_minute:
            return max(0.0, starts[0] + WINDOW_S - now)
        starts.append(now)
        self._forget_idle(now)
        return None

    def first_refusal(self, person: str) -> bool:
        """Whether this refusal is the first of ``person``'s current window (to say it once)."""
        now = self._now()
        told = self._told.get(person)
        if told is not None and told > now - WINDOW_S:
            return False
        self._told[person] = now
        return True

    def _forget_idle(self, now: float) -> None:
        if len(self._starts) > 1024:  # people idle for a minute hold nothing
            self._starts = {p: s for p, s in self._starts.items() if s and s[-1] > now - WINDOW_S}
            self._told = {p: t for p, t in self._told.items() if t > now - WINDOW_S}


def refusal_text(person_name: str, per_minute: int, wait_s: float) -> str:
    """The one-line answer, for the API and for a direct message alike."""
    return (
        f"Too many requests from {person_name}: at most {per_minute} a minute. "
        f"Please try again in {max(1, round(wait_s))} s."
    )
