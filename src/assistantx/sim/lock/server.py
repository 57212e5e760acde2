"""The lock emulator: a ``LockController`` behind an asyncio TCP server.

Requests (after the handshake, see ``link``) are ``{"id": int, "op": str, ...}``; each gets
``{"type": "response", "id", "ok": true, "result"}`` or ``{"type": "response", "id", "ok":
false, "error": {"type", "kind"/"reason", "message"}}``. Ops: ``ping``, ``status``,
``provision {payload}``, ``revoke {code_id}``, ``open {reason}``, ``subscribe {since,
epoch}``, ``reload_keys``, and the simulation commands ``scan {payload}`` and ``close``.

After ``subscribe`` the server pushes ``{"type": "event", "event": LockEvent}``: first the
logged events after ``since``, then live ones, in sequence order. Registration and backlog
happen in one step with no await in between, so no event falls in a crack.

Nothing a client sends can crash the server: each connection is its own task, bounded by a
handshake timeout, a per-frame timeout, an idle timeout, a frame size limit, a connection
limit and a bounded outbound queue (a client too slow to read its events is dropped; it
resumes from its last sequence when it reconnects).

Connections are counted in two pools. *Pending* ones have not authenticated yet: they get a
short handshake deadline, and at most ``max_pending_per_peer`` per peer address and
``max_pending`` in all. A new connection beyond the per-address bound evicts that address's
oldest pending one; beyond the overall bound, the oldest pending connection of the address
holding the most goes, so a flood spread over many addresses is paid for by those addresses,
never by the assistant's one socket. A newcomer is never refused: nothing tells the
assistant's fresh socket from an attacker's before the key, and refusing newcomers while the
pool is full of young silent sockets let a churning flood from the assistant's own address
keep it out for as long as the flood lasted. Evicting the oldest instead, the assistant's
handshake only has to finish before ``max_pending_per_peer`` more connections from its address
arrive (one round trip; the per-address budget is generous for that reason), and a silent
socket holds its place no longer than that many newcomers. Only *sessions*, which proved the
shared key, count against ``max_connections``.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from collections import Counter
from collections.abc import Callable
from typing import Any

from assistantx.adapters.lock.protocol.frames import DEFAULT_MAX_FRAME
from assistantx.adapters.lock.protocol.keys import Keyring
from assistantx.adapters.lock.protocol.link import (
    Hello,
    LinkTimeouts,
    SecureChannel,
    close_writer,
    server_handshake,
)
from assistantx.core.errors import (
    InvalidCodeError,
    LockCommandError,
    LockError,
    LockProtocolError,
)
from assistantx.core.ports.lock import LockEvent
from assistantx.sim.lock.controller import LockController

logger = logging.getLogger(__name__)

OUTBOUND_QUEUE_SIZE = 1024


class _BadRequest(Exception):
    """A well-framed, authenticated request that makes no sense; answered, not fatal."""


class LockServer:
    def __init__(
        self,
        controller: LockController,
        link_key: bytes,
        *,
        host: str = "127.0.0.1",
        port: int = 0,
        timeouts: LinkTimeouts | None = None,
        max_frame: int = DEFAULT_MAX_FRAME,
        max_connections: int = 32,
        max_pending: int = 256,
        max_pending_per_peer: int = 64,
        reload_keys: Callable[[], Keyring] | None = None,
    ) -> None:
        """``max_connections``: authenticated sessions; ``max_pending`` and
        ``max_pending_per_peer``: connections still in the handshake (the oldest evicted)."""
        if min(max_connections, max_pending, max_pending_per_peer) < 1:
            raise ValueError("connection limits must be at least 1")
        self.controller = controller
        self.link_key = link_key
        self.host = host
        self.port = port
        self.timeouts = timeouts or LinkTimeouts()
        self.max_frame = max_frame
        self.max_connections = max_connections
        self._reload_keys = reload_keys
        self._server: asyncio.Server | None = None
        self.max_pending = max_pending
        self.max_pending_per_peer = max_pending_per_peer
        self._connections: set[asyncio.Task[None]] = set()
        # Connections still in the handshake, oldest first, with their peer address.
        self._pending: dict[asyncio.Task[None], str] = {}
        self._sessions: set[asyncio.Task[None]] = set()
        self.refused_handshakes = 0
        self.evicted_pending = 0

    @property
    def address(self) -> tuple[str, int]:
        if self._server is None:
            raise LockError("the lock server is not running")
        host, port = self._server.sockets[0].getsockname()[:2]
        return str(host), int(port)

    @property
    def connection_count(self) -> int:
        return len(self._connections)

    @property
    def session_count(self) -> int:
        """Authenticated connections."""
        return len(self._sessions)

    @property
    def pending_count(self) -> int:
        """Connections still in the handshake."""
        return len(self._pending)

    async def start(self) -> tuple[str, int]:
        if self._server is None:
            self._server = await asyncio.start_server(
                self._accept, self.host, self.port, limit=self.max_frame + 64
            )
            logger.info("lock %s listening on %s:%s", self.controller.lock_id, *self.address)
        return self.address

    async def stop(self) -> None:
        server, self._server = self._server, None
        if server is None:
            return
        server.close()
        for task in list(self._connections):
            task.cancel()
        await asyncio.gather(*self._connections, return_exceptions=True)
        await server.wait_closed()

    async def serve_forever(self) -> None:
        await self.start()
        assert self._server is not None
        await self._server.serve_forever()

    def reload_keys(self) -> Keyring:
        """Adopt the keyring from the configured source (the key file), in place."""
        if self._reload_keys is None:
            raise LockCommandError("no_key_source", "this lock has no key file to reload")
        fresh = self._reload_keys()
        self.controller.keyring.replace_with(fresh)
        logger.info("lock %s: code keys reloaded: %s", self.controller.lock_id, fresh)
        return self.controller.keyring

    def reload_keys_logged(self) -> None:
        """For a signal handler: reload, and log instead of raising."""
        try:
            self.reload_keys()
        except Exception:
            logger.exception("lock %s: key reload failed; old keys kept", self.controller.lock_id)

    def _make_room_for(self, peer: str) -> None:
        """Evict the oldest pending connections so that one more from ``peer`` fits."""
        from_peer = [t for t, p in self._pending.items() if p == peer]
        while len(from_peer) >= self.max_pending_per_peer:
            self._evict(from_peer.pop(0))
        while len(self._pending) >= self.max_pending:
            # From the peer holding the most pending connections: a flood spread over many
            # addresses is paid for by its own addresses, not by the assistant's one socket.
            busiest = Counter(self._pending.values()).most_common(1)[0][0]
            self._evict(next(t for t, p in self._pending.items() if p == busiest))

    def _evict(self, task: asyncio.Task[None]) -> None:
        peer = self._pending.pop(task, "?")
        self.evicted_pending += 1
        if self.evicted_pending == 1 or self.evicted_pending % 100 == 0:
            logger.warning(
                "lock: unauthenticated connections piling up (from %s); evicted %d so far",
                peer,
                self.evicted_pending,
            )
        task.cancel()

    async def _accept(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        peername = writer.get_extra_info("peername")
        peer = str(peername[0]) if isinstance(peername, tuple) and peername else "?"
        self._make_room_for(peer)
        # The connection runs in a task of its own, so stop() cancels it without cancelling
        # the stream callback's task (which asyncio reports as an unhandled error).
        task = asyncio.create_task(self._serve_connection(reader, writer))
        self._connections.add(task)
        self._pending[task] = peer
        try:
            await task
        except asyncio.CancelledError:
            if not task.cancelled():
                raise  # we ourselves are being cancelled, not just the connection
        except Exception:
            # A bug in one connection must never take the emulator down.
            logger.exception("lock: connection handler failed")
        finally:
            self._connections.discard(task)
            self._pending.pop(task, None)
            self._sessions.discard(task)
            await close_writer(writer)

    async def _serve_connection(
        self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter
    ) -> None:
        peer = writer.get_extra_info("peername")
        try:
            channel = await server_handshake(
                reader,
                writer,
                link_key=self.link_key,
                hello=Hello(self.controller.lock_id, self.controller.epoch),
                handshake_s=self.timeouts.handshake_s,
                max_frame=self.max_frame,
                frame_timeout=self.timeouts.frame_s,
            )
        except LockError as exc:
            self.refused_handshakes += 1
            logger.info("lock: handshake with %s failed: %s", peer, exc)
            return
        task = asyncio.current_task()
        assert task is not None
        self._pending.pop(task, None)
        if len(self._sessions) >= self.max_connections:
            logger.warning(
                "lock: session limit %s reached; refusing %s", self.max_connections, peer
            )
            return
        self._sessions.add(task)
        logger.info("lock: %s authenticated", peer)
        session = _Session(self, channel)
        await session.run()
        logger.info("lock: %s disconnected", peer)


class _Session:
    """One authenticated client: a reader loop and a writer task over one outbound queue."""

    def __init__(self, server: LockServer, channel: SecureChannel) -> None:
        self.server = server
        self.controller = server.controller
        self.channel = channel
        self.outbound: asyncio.Queue[dict[str, Any]] = asyncio.Queue(OUTBOUND_QUEUE_SIZE)
        self.overflowed = asyncio.Event()
        self.subscribed = False

    async def run(self) -> None:
        writer = asyncio.create_task(self._write_loop())
        try:
            await self._read_loop()
        except LockError as exc:
            logger.info("lock: closing a session: %s", exc)
        finally:
            self.controller.remove_listener(self._on_event)
            writer.cancel()
            with contextlib.suppress(asyncio.CancelledError, LockError):
                await writer

    async def _read_loop(self) -> None:
        while not self.overflowed.is_set():
            message = await self.channel.receive(idle_timeout=self.server.timeouts.idle_s)
            self._handle(message)

    async def _write_loop(self) -> None:
        try:
            while True:
                await self.channel.send(await self.outbound.get())
        except LockError as exc:
            logger.info("lock: cannot write to a client: %s", exc)
            self.overflowed.set()
            # Wake the reader so the session ends now rather than at the idle timeout.
            self.channel.writer.close()

    def _push(self, message: dict[str, Any]) -> None:
        try:
            self.outbound.put_nowait(message)
        except asyncio.QueueFull:
            logger.warning("lock: a client is not reading its events; dropping it")
            self.overflowed.set()
            self.channel.writer.close()

    def _on_event(self, event: LockEvent) -> None:
        self._push({"type": "event", "event": event.model_dump(mode="json")})

    def _handle(self, message: dict[str, Any]) -> None:
        request_id = message.get("id")
        if not isinstance(request_id, int) or isinstance(request_id, bool):
            raise LockProtocolError("request without an integer id")
        try:
            result = self._dispatch(message)
        except InvalidCodeError as exc:
            error: dict[str, Any] = {"type": "invalid_code", "reason": exc.reason}
            self._respond_error(request_id, error, str(exc))
        except LockCommandError as exc:
            self._respond_error(request_id, {"type": "command", "kind": exc.kind}, str(exc))
        except _BadRequest as exc:
            self._respond_error(request_id, {"type": "bad_request"}, str(exc))
        else:
            self._push({"type": "response", "id": request_id, "ok": True, "result": result})
            if message.get("op") == "subscribe":
                self._start_stream(message)

    def _respond_error(self, request_id: int, error: dict[str, Any], text: str) -> None:
        error["message"] = text
        self._push({"type": "response", "id": request_id, "ok": False, "error": error})

    def _dispatch(self, message: dict[str, Any]) -> dict[str, Any]:
        op = message.get("op")
        c = self.controller
        match op:
            case "ping":
                return {"time": c.clock.now()}
            case "status":
                return c.status().model_dump(mode="json")
            case "provision":
                claims = c.provision(_text(message, "payload"))
                return {"code_id": claims.code_id, "expires_at": claims.expires_at}
            case "revoke":
                c.revoke(_text(message, "code_id"))
                return {}
            case "open":
                reason = message.get("reason", "")
                if not isinstance(reason, str):
                    raise _BadRequest("'reason' must be text")
                return {"event": c.open_for_maintenance(reason).model_dump(mode="json")}
            case "scan":
                result = c.scan(_text(message, "payload"))
                return {"events": [e.model_dump(mode="json") for e in result.events]}
            case "close":
                return {"event": c.close().model_dump(mode="json")}
            case "subscribe":
                since, epoch = message.get("since", 0), message.get("epoch")
                if not isinstance(since, int) or isinstance(since, bool) or since < 0:
                    raise _BadRequest("'since' must be a non-negative integer")
                if epoch is not None and not isinstance(epoch, str):
                    raise _BadRequest("'epoch' must be text or null")
                if self.subscribed:
                    raise _BadRequest("already subscribed")
                backlog = c.events_since(since, epoch)
                return {"epoch": backlog.epoch, "complete": backlog.complete}
            case "reload_keys":
                keyring = self.server.reload_keys()
                return {"current": keyring.current_id, "key_ids": keyring.key_ids()}
            case _:
                raise _BadRequest(f"unknown op {op!r}")

    def _start_stream(self, message: dict[str, Any]) -> None:
        # Backlog and registration in one synchronous step: no event is lost or doubled.
        backlog = self.controller.events_since(message.get("since", 0), message.get("epoch"))
        for event in backlog.events:
            self._on_event(event)
        self.controller.add_listener(self._on_event)
        self.subscribed = True


def _text(message: dict[str, Any], name: str) -> str:
    value = message.get(name)
    if not isinstance(value, str):
        raise _BadRequest(f"{name!r} must be text")
    return value
