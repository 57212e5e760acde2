"""When to try an LLM call again, and how long to wait first.

Exponential backoff with full jitter (``core.backoff``): the n-th retry waits between 0 and
``min(max_delay_s, base_delay_s * 2**n)``, drawn from a generator seeded by ``seed`` so a
run is reproducible. A server's ``Retry-After`` (seconds, or an HTTP date) replaces the computed
delay but is capped at ``retry_after_cap_s``: a server asking for an hour must not stall an
instruction for an hour; the retry budget then runs out and the caller sees an error.
"""

from __future__ import annotations

import random
import time
from dataclasses import dataclass, field
from email.utils import parsedate_to_datetime

from assistantx.core.backoff import Backoff

RETRYABLE_STATUS = frozenset({408, 409, 425, 429})


def is_retryable_status(status_code: int) -> bool:
    """429 and the other "try later" codes, and every server error."""
    return status_code in RETRYABLE_STATUS or status_code >= 500


def parse_retry_after(value: str | None, *, now: float | None = None) -> float | None:
    """Seconds to wait from a ``Retry-After`` header value, or None when absent or unusable.

    Accepts delta-seconds (fractions too, some proxies send them) and HTTP dates; a date in
    the past means "now" (0 s).
    """
    if value is None:
        return None
    text = value.strip()
    if not text:
        return None
    try:
        seconds = float(text)
    except ValueError:
        pass
    else:
        return max(0.0, seconds) if seconds == seconds else None  # NaN is unusable
    try:
        when = parsedate_to_datetime(text)
    except (TypeError, ValueError, IndexError):
        return None
    if when.tzinfo is None:  # RFC 9110 dates are GMT; a naive one came without a zone
        return None
    current = time.time() if now is None else now
    return max(0.0, when.timestamp() - current)


@dataclass
class RetryPolicy:
    """How often to retry a failed call and how long to wait between tries; one per model."""

    max_retries: int = 4
    base_delay_s: float = 0.5
    max_delay_s: float = 8.0
    retry_after_cap_s: float = 30.0
    seed: int | None = 0
    _rng: random.Random = field(init=False, repr=False)

    def __post_init__(self) -> None:
        if self.max_retries < 0:
            raise ValueError("max_retries must be >= 0")
        if self.base_delay_s < 0 or self.max_delay_s < 0 or self.retry_after_cap_s < 0:
            raise ValueError("delays must be >= 0")
        self._rng = random.Random(self.seed)

    def delay_s(self, retry_index: int, retry_after_s: float | None = None) -> float:
        """The wait before retry number ``retry_index`` (0 for the first retry)."""
        if retry_after_s is not None:
            return min(retry_after_s, self.retry_after_cap_s)
        return Backoff(self.base_delay_s, self.max_delay_s).delay_s(retry_index, self._rng)
