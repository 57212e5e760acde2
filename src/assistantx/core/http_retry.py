"""One retrying httpx transport for every HTTP client of ours (the model server, Matrix).

:class:`RetryingTransport` wraps another transport and sends a request again when the server
says "try later" (429, 408, 409, 425 and every 5xx) or cannot be reached, waiting per
:class:`RetryPolicy`: exponential backoff with full jitter (``core.backoff``), or the
server's own hint (``Retry-After`` in seconds or as an HTTP date; a client may read another,
as Matrix's ``retry_after_ms``), capped so that a server asking for an hour cannot stall an
instruction for an hour. Timeouts are retried only when the policy says so: a model server
that timed out is usually still busy with the same prompt.

Every try is appended to the list a caller passes in the request's extensions under
:data:`TRIES` (``client.post(..., extensions={TRIES: tries})``), so a caller that pays per
request (the model's token accounting) sees each one: answered, refused, timed out or failed.
The request body must be replayable (``json=`` and ``content=`` bytes are).

Closing waits (up to :data:`CLOSE_GRACE_S`) for the requests still in flight before it closes
the pool: a request another task started just before shutdown may be opening a connection,
and closing the pool under it leaves that socket to the garbage collector, unclosed.
"""

from __future__ import annotations

import asyncio
import logging
import random
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from email.utils import parsedate_to_datetime
from typing import Literal

import httpx

from assistantx.core.backoff import Backoff

logger = logging.getLogger(__name__)

TRIES = "assistantx.tries"  # request extension: a list[Try] the transport appends to
RETRYABLE_STATUS = frozenset({408, 409, 425, 429})
CLOSE_GRACE_S = 2.0
"""How long closing waits for requests in flight before it closes their connections."""

TryOutcome = Literal["answered", "refused", "timed_out", "failed"]


@dataclass(frozen=True)
class Try:
    """One request as sent: ``answered`` (with its HTTP ``status``), ``refused`` (no
    connection: the server never saw it), ``timed_out`` or ``failed`` (the connection broke)."""

    outcome: TryOutcome
    status: int | None = None
    error: str = ""

    @property
    def reached_server(self) -> bool:
        return self.outcome != "refused"


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


def header_retry_after(response: httpx.Response) -> float | None:
    """The server's wait hint: its ``Retry-After`` header."""
    return parse_retry_after(response.headers.get("retry-after"))


@dataclass
class RetryPolicy:
    """How often to retry a failed request and how long to wait between tries."""

    max_retries: int = 4
    base_delay_s: float = 0.5
    max_delay_s: float = 8.0
    retry_after_cap_s: float = 30.0
    retry_timeouts: bool = True
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


class RetryingTransport(httpx.AsyncBaseTransport):
    """Retries what the server says to retry; see the module's docstring."""

    def __init__(
        self,
        policy: RetryPolicy | None = None,
        inner: httpx.AsyncBaseTransport | None = None,
        *,
        retry_after: Callable[[httpx.Response], float | None] = header_retry_after,
        final: Callable[[httpx.Request, httpx.Response], bool] | None = None,
    ) -> None:
        self.policy = policy or RetryPolicy()
        self._inner = inner or httpx.AsyncHTTPTransport()
        self._retry_after = retry_after
        # an answer with a retryable status that the client knows is final (its body read)
        self._final = final
        self._in_flight = 0
        self._closing = False  # once closing, nothing is retried (a retry opens a connection)
        self._idle = asyncio.Event()
        self._idle.set()

    @property
    def in_flight(self) -> int:
        """Requests being sent (their tries and waits included) right now."""
        return self._in_flight

    async def handle_async_request(self, request: httpx.Request) -> httpx.Response:
        self._in_flight += 1
        self._idle.clear()
        try:
            return await self._send_with_retries(request)
        finally:
            self._in_flight -= 1
            if self._in_flight == 0:
                self._idle.set()

    async def _send_with_retries(self, request: httpx.Request) -> httpx.Response:
        tries: list[Try] = request.extensions.get(TRIES, [])
        retries = self.policy.max_retries
        for attempt in range(retries + 1):
            last = attempt == retries or self._closing
            try:
                response = await self._inner.handle_async_request(request)
            except httpx.TimeoutException as exc:
                tries.append(Try("timed_out", error=type(exc).__name__))
                if last or not self.policy.retry_timeouts:
                    raise
                reason, hint = f"no answer in time ({type(exc).__name__})", None
            except httpx.ConnectError as exc:
                tries.append(Try("refused", error=str(exc)))
                if last:
                    raise
                reason, hint = f"cannot connect ({exc})", None
            except httpx.TransportError as exc:
                tries.append(Try("failed", error=f"{type(exc).__name__}: {exc}"))
                if last:
                    raise
                reason, hint = f"connection failed ({type(exc).__name__})", None
            else:
                tries.append(Try("answered", status=response.status_code))
                if last or not is_retryable_status(response.status_code):
                    return response
                await response.aread()  # the hint may be in the body (Matrix)
                if self._final is not None and self._final(request, response):
                    return response
                hint = self._retry_after(response)
                await response.aclose()
                reason = f"HTTP {response.status_code}"
            delay_s = self.policy.delay_s(attempt, hint)
            logger.warning(
                "%s %s: %s; retry %d of %d in %.2f s",
                request.method,
                request.url.path,
                reason,
                attempt + 1,
                retries,
                delay_s,
            )
            await asyncio.sleep(delay_s)
        raise AssertionError("unreachable: the last try returns or raises")

    async def aclose(self) -> None:
        self._closing = True
        if self._in_flight:
            try:
                await asyncio.wait_for(self._idle.wait(), CLOSE_GRACE_S)
            except TimeoutError:
                logger.warning(
                    "closing with %d request(s) still in flight after %.1f s",
                    self._in_flight,
                    CLOSE_GRACE_S,
                )
        await self._inner.aclose()
