"""The assistant's end of the lock link: requests, an event stream, reconnects.

``LockClient`` keeps one authenticated connection to the lock. A supervisor task connects,
subscribes to events from the last sequence it saw, pings every ``keepalive_s`` and, when
the link drops (or a ping goes unanswered: a half-open connection), reconnects with
exponential backoff and full jitter (``core.backoff``). Events are delivered once each, in
order: the lock replays what the client missed, and anything at or below the last seen
sequence is dropped as a duplicate. A changed ``epoch`` (the lock restarted) starts the count over.

Requests are not retried across a reconnect: ``scan`` or ``close`` are not idempotent, so a
request whose connection dies fails with ``LockConnectionError`` and the caller decides.
A wrong shared key is not retried either: it will not fix itself.
"""

from __future__ import annotations

import asyncio
import contextlib
import itertools
import logging
import random
from collections.abc import Callable
from typing import Any

from assistantx.adapters.lock.protocol.frames import DEFAULT_MAX_FRAME
from assistantx.adapters.lock.protocol.link import (
    LinkTimeouts,
    SecureChannel,
    client_handshake,
    close_writer,
)
from assistantx.core.backoff import Backoff
from assistantx.core.errors import (
    InvalidCodeError,
    LockAuthError,
    LockCommandError,
    LockConnectionError,
    LockError,
    LockProtocolError,
    LockTimeoutError,
)
from assistantx.core.lifecycle import Component
from assistantx.core.ports.lock import LockEvent

logger = logging.getLogger(__name__)

EventCallback = Callable[[LockEvent], None]
_ResultHook = Callable[[dict[str, Any]], None]


class LockClient(Component):
    """One supervised connection to the lock; ``start`` waits for the first one (a started
    client runs its supervisor as a tracked task)."""

    def __init__(
        self,
        host: str,
        port: int,
        link_key: bytes,
        *,
        lock_id: str | None = None,
        timeouts: LinkTimeouts | None = None,
        backoff: Backoff | None = None,
        max_frame: int = DEFAULT_MAX_FRAME,
        on_event: EventCallback | None = None,
        rng: random.Random | None = None,
    ) -> None:
        super().__init__()
        self.host = host
        self.port = port
        self.expected_lock_id = lock_id
        self.timeouts = timeouts or LinkTimeouts()
        self.backoff = backoff or Backoff()
        self.max_frame = max_frame
        self.on_event = on_event
        self._link_key = link_key
        self._rng = rng or random.Random()
        self._ids = itertools.count(1)
        self._pending: dict[int, tuple[asyncio.Future[dict[str, Any]], _ResultHook | None]] = {}
        self._channel: SecureChannel | None = None
        self._ready = asyncio.Event()
        self._first_outcome: asyncio.Future[None] | None = None
        self._fatal: LockError | None = None
        # What the client knows of the lock and its event stream.
        self.lock_id: str | None = None
        self.epoch: str | None = None
        self.last_seq = 0
        self.duplicates_dropped = 0
        self.gaps = 0  # times the lock's bounded log had already dropped events we missed
        self.connections = 0

    @property
    def connected(self) -> bool:
        return self._ready.is_set()

    # -- lifecycle ----------------------------------------------------------------------

    async def _start(self) -> None:
        """Connect and subscribe; raises if the first connection fails within connect_s
        (and the component stops again, its supervisor cancelled)."""
        self._fatal = None
        self._first_outcome = asyncio.get_running_loop().create_future()
        self.create_task(self._supervise(), name="lock-client")
        try:
            async with asyncio.timeout(self.timeouts.connect_s):
                await asyncio.shield(self._first_outcome)
        except TimeoutError as exc:
            raise LockConnectionError(
                f"cannot reach the lock at {self.host}:{self.port} within "
                f"{self.timeouts.connect_s} s"
            ) from exc

    async def _stop(self) -> None:
        self._ready.clear()

    async def drop_connection(self) -> None:
        """Close the current connection as a network fault would; the client reconnects."""
        channel = self._channel
        if channel is not None:
            channel.writer.transport.abort()

    # -- requests -----------------------------------------------------------------------

    async def request(self, op: str, **args: Any) -> dict[str, Any]:
        """Send one command and return its result, or raise the matching ``LockError``."""
        if self._fatal is not None:
            raise self._fatal
        if not self.started:
            raise LockConnectionError("the lock client is not started")
        try:
            async with asyncio.timeout(self.timeouts.request_s):
                await self._ready.wait()
        except TimeoutError as exc:
            raise LockConnectionError(
                f"not connected to the lock at {self.host}:{self.port}"
            ) from exc
        channel = self._channel
        assert channel is not None
        return await self._call(channel, op, args)

    async def _call(
        self,
        channel: SecureChannel,
        op: str,
        args: dict[str, Any],
        hook: _ResultHook | None = None,
    ) -> dict[str, Any]:
        request_id = next(self._ids)
        future: asyncio.Future[dict[str, Any]] = asyncio.get_running_loop().create_future()
        self._pending[request_id] = (future, hook)
        try:
            await channel.send({"id": request_id, "op": op, **args})
            async with asyncio.timeout(self.timeouts.request_s):
                return await future
        except TimeoutError as exc:
            raise LockTimeoutError(
                f"no answer to {op!r} within {self.timeouts.request_s} s"
            ) from exc
        finally:
            self._pending.pop(request_id, None)

    # -- the connection -----------------------------------------------------------------

    async def _supervise(self) -> None:
        attempt = 0
        failing = False
        while True:
            try:
                channel = await self._connect()
            except LockAuthError as exc:
                self._fatal = exc
            except (LockError, OSError) as exc:
                if not failing:
                    logger.warning("lock %s:%s unreachable: %s", self.host, self.port, exc)
                    failing = True
                await asyncio.sleep(self.backoff.delay_s(attempt, self._rng))
                attempt += 1
                continue
            if self._fatal is not None:
                logger.error("lock %s:%s: %s", self.host, self.port, self._fatal)
                self._settle_first(self._fatal)
                return
            if failing:
                logger.warning("lock %s:%s reachable again", self.host, self.port)
                failing = False
            attempt = 0
            try:
                await self._run_session(channel)
            except LockError as exc:
                # A LockAuthError here is a frame that failed its MAC: someone is tampering.
                level = logging.ERROR if isinstance(exc, LockAuthError) else logging.INFO
                logger.log(level, "lock link lost: %s", exc)
            finally:
                self._ready.clear()
                self._channel = None
                self._fail_pending(LockConnectionError("the connection to the lock was lost"))
                await channel.close()
            await asyncio.sleep(self.backoff.delay_s(0, self._rng))

    async def _connect(self) -> SecureChannel:
        try:
            async with asyncio.timeout(self.timeouts.connect_s):
                reader, writer = await asyncio.open_connection(
                    self.host, self.port, limit=self.max_frame + 64
                )
        except TimeoutError as exc:
            raise LockTimeoutError("TCP connect timed out") from exc
        try:
            channel, hello = await client_handshake(
                reader,
                writer,
                link_key=self._link_key,
                handshake_s=self.timeouts.connect_s,
                expected_lock_id=self.expected_lock_id,
                max_frame=self.max_frame,
                frame_timeout=self.timeouts.frame_s,
            )
        except BaseException:
            await close_writer(writer)
            raise
        self.lock_id = hello.lock_id
        return channel

    async def _run_session(self, channel: SecureChannel) -> None:
        reader = asyncio.create_task(self._read_loop(channel))
        try:
            subscribe_args = {"since": self.last_seq, "epoch": self.epoch}
            await self._call(channel, "subscribe", subscribe_args, hook=self._on_subscribed)
            self._channel = channel
            self.connections += 1
            self._ready.set()
            self._settle_first(None)
            keepalive = asyncio.create_task(self._keepalive(channel))
            done, _ = await asyncio.wait({reader, keepalive}, return_when=asyncio.FIRST_COMPLETED)
            keepalive.cancel()
            with contextlib.suppress(asyncio.CancelledError, LockError):
                await keepalive
            for task in done:
                task.result()  # re-raise what ended the session
        finally:
            reader.cancel()
            with contextlib.suppress(asyncio.CancelledError, LockError):
                await reader

    def _on_subscribed(self, result: dict[str, Any]) -> None:
        # Runs inside the reader, before the replayed events that follow this response.
        epoch = result.get("epoch")
        if not isinstance(epoch, str):
            raise LockProtocolError("subscribe answer lacks an epoch")
        if self.epoch is not None and epoch != self.epoch:
            logger.warning("the lock restarted (new epoch); its event count starts over")
            self.last_seq = 0
        if self.epoch is not None and not result.get("complete", True):
            self.gaps += 1
            logger.warning("the lock's event log no longer holds every event we missed")
        self.epoch = epoch

    async def _keepalive(self, channel: SecureChannel) -> None:
        while True:
            await asyncio.sleep(self.timeouts.keepalive_s)
            await self._call(channel, "ping", {})

    async def _read_loop(self, channel: SecureChannel) -> None:
        try:
            while True:
                message = await channel.receive(idle_timeout=None)
                kind = message.get("type")
                if kind == "event":
                    self._on_event_frame(message)
                elif kind == "response":
                    self._on_response(message)
                else:
                    raise LockProtocolError(f"unexpected frame type {kind!r}")
        finally:
            # Whoever waits for an answer learns now, not at its timeout.
            self._fail_pending(LockConnectionError("the connection to the lock was lost"))

    def _on_event_frame(self, message: dict[str, Any]) -> None:
        try:
            event = LockEvent.model_validate(message.get("event"))
        except ValueError as exc:
            raise LockProtocolError(f"malformed event: {exc}") from exc
        if event.seq <= self.last_seq:
            self.duplicates_dropped += 1
            return
        if event.seq != self.last_seq + 1 and self.last_seq:
            logger.warning("lock events %s..%s were lost", self.last_seq + 1, event.seq - 1)
        self.last_seq = event.seq
        if self.on_event is not None:
            try:
                self.on_event(event)
            except Exception:
                logger.exception("lock event callback failed")

    def _on_response(self, message: dict[str, Any]) -> None:
        request_id = message.get("id")
        entry = self._pending.get(request_id) if isinstance(request_id, int) else None
        if entry is None:
            logger.debug("lock: answer to a forgotten request %r", request_id)
            return
        future, hook = entry
        if future.done():
            return
        if message.get("ok") is True:
            result = message.get("result")
            if not isinstance(result, dict):
                future.set_exception(LockProtocolError("response without a result object"))
                return
            if hook is not None:
                try:
                    hook(result)
                except LockError as exc:
                    future.set_exception(exc)
                    return
            future.set_result(result)
        else:
            future.set_exception(_error_from(message.get("error")))

    def _fail_pending(self, error: LockError) -> None:
        for future, _ in self._pending.values():
            if not future.done():
                future.set_exception(error)

    def _settle_first(self, error: LockError | None) -> None:
        first = self._first_outcome
        if first is None or first.done():
            return
        if error is None:
            first.set_result(None)
        else:
            first.set_exception(error)
            # Retrieved by start(), or nobody if it already timed out; either way, no warning.
            first.exception()


def _error_from(error: Any) -> LockError:
    if not isinstance(error, dict):
        return LockProtocolError("error response without details")
    message = str(error.get("message", "the lock refused the command"))
    match error.get("type"):
        case "invalid_code":
            return InvalidCodeError(str(error.get("reason", "malformed")), message)
        case "command":
            return LockCommandError(str(error.get("kind", "refused")), message)
        case _:
            return LockProtocolError(message)
