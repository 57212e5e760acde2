"""Per-event isolation on the inbound paths: one event that breaks its handler is logged with
its id, counted, and skipped; the events around it go on, and the batch it came in is
acknowledged (mautrix-python's ``AppService`` transaction handling does the same). Failures
that are no event's fault (the store cannot write, nothing consumes the inbox) still fail the
batch, so the homeserver or the poller brings it again.

``SkippedEvents`` is the count, by inbound path (``matrix_push``, ``matrix_sync``,
``dispatch``); the service exposes it on ``/metrics`` as
``assistantx_inbound_events_skipped_total``.
"""

from __future__ import annotations

import logging
from collections import Counter

logger = logging.getLogger(__name__)


class SkippedEvents:
    """How many inbound events each path skipped because handling them raised."""

    def __init__(self, *paths: str) -> None:
        """``paths``: those shown (at 0) before anything is skipped on them."""
        self.by_path: Counter[str] = Counter(dict.fromkeys(paths, 0))

    def skip(self, path: str, event_id: object, stage: str, error: BaseException) -> None:
        """Log ``error`` (with its traceback) against ``event_id`` and count it for ``path``."""
        self.by_path[path] += 1
        logger.error(
            "skipped inbound event %s on %s: %s failed: %s: %s",
            printable(event_id) if isinstance(event_id, str) else "(no event id)",
            path,
            stage,
            type(error).__name__,
            printable(str(error)),
            exc_info=error,
        )

    @property
    def total(self) -> int:
        return sum(self.by_path.values())


def printable(text: str, limit: int = 200) -> str:
    """``text`` safe for any log handler: lone surrogates escaped, at most ``limit`` chars (an
    event id is whatever the sender made of it)."""
    safe = text.encode("utf-8", "backslashreplace").decode("utf-8")
    return safe if len(safe) <= limit else safe[: limit - 1] + "…"
