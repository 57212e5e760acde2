"""The authenticated lock link: a mutual challenge–response, then MAC'd frames.

Handshake (plain JSON frames, ``K`` = the shared link key)::

    lock      -> assistant  {"type": "hello", "version": 1, "lock_id", "epoch", "nonce": Ns}
    assistant -> lock       {"type": "auth", "version": 1, "nonce": Nc,
                             "mac": HMAC(K, "client" | lock_id | Ns | Nc)}
    lock      -> assistant  {"type": "auth_ok", "mac": HMAC(K, "server" | lock_id | Ns | Nc)}
                            or {"type": "auth_failed"} and the lock hangs up

Both sides prove they hold ``K`` over both fresh nonces, so nobody on the network can open
the door or fake the lock's events, and a recorded handshake is worth nothing later. Then
``S = HMAC(K, "session" | Ns | Nc)`` and every frame is ``HMAC(S, direction | counter |
body) | body``: the counter (never sent, counted by both ends) stops replayed, dropped,
reordered or reflected frames within the connection. Frames are authenticated, not
encrypted: nothing on the link is secret (QR payloads are sealed on their own).
"""

from __future__ import annotations

import asyncio
import binascii
import contextlib
import hashlib
import hmac
import logging
import secrets
from dataclasses import dataclass
from typing import Any

from assistantx.adapters.lock.protocol.frames import (
    DEFAULT_MAX_FRAME,
    decode_message,
    encode_frame,
    encode_message,
    read_frame,
)
from assistantx.adapters.lock.protocol.keys import b64decode, b64encode
from assistantx.core.errors import LockAuthError, LockConnectionError, LockProtocolError

logger = logging.getLogger(__name__)

PROTOCOL_VERSION = 1
NONCE_BYTES = 16
MAC_BYTES = 32
_TO_CLIENT = b"lock->assistant"
_TO_SERVER = b"assistant->lock"


@dataclass(frozen=True)
class LinkTimeouts:
    """Every wait on the link, in seconds; tests use short ones."""

    connect_s: float = 5.0  # TCP connect + handshake, client side
    handshake_s: float = 2.0  # whole handshake, server side (slowloris guard; one round trip)
    frame_s: float = 5.0  # first byte to last byte of one frame
    idle_s: float = 30.0  # server hangs up on a client silent this long (half-open guard)
    keepalive_s: float = 10.0  # client pings this often; keep it well under idle_s
    request_s: float = 5.0  # a command's answer, and a ping's

    def __post_init__(self) -> None:
        if (
            min(
                self.connect_s,
                self.handshake_s,
                self.frame_s,
                self.idle_s,
                self.keepalive_s,
                self.request_s,
            )
            <= 0
        ):
            raise ValueError("link timeouts must be positive")


@dataclass(frozen=True)
class Hello:
    lock_id: str
    epoch: str


def _mac(key: bytes, *parts: bytes) -> bytes:
    mac = hmac.new(key, digestmod=hashlib.sha256)
    for part in parts:
        # Length-prefix each part so no two different part lists hash the same.
        mac.update(len(part).to_bytes(4, "big"))
        mac.update(part)
    return mac.digest()


class SecureChannel:
    """One authenticated connection; ``send`` and ``receive`` carry JSON objects."""

    def __init__(
        self,
        reader: asyncio.StreamReader,
        writer: asyncio.StreamWriter,
        session_key: bytes,
        *,
        is_server: bool,
        max_frame: int,
        frame_timeout: float,
    ) -> None:
        self.reader = reader
        self.writer = writer
        self._key = session_key
        self._out_label, self._in_label = (
            (_TO_CLIENT, _TO_SERVER) if is_server else (_TO_SERVER, _TO_CLIENT)
        )
        self._out_counter = 0
        self._in_counter = 0
        self._max_frame = max_frame
        self._frame_timeout = frame_timeout
        self._send_lock = asyncio.Lock()

    async def send(self, message: dict[str, Any]) -> None:
        body = encode_message(message)
        async with self._send_lock:
            counter = self._out_counter.to_bytes(8, "big")
            self._out_counter += 1
            frame = encode_frame(
                _mac(self._key, self._out_label, counter, body) + body, self._max_frame
            )
            try:
                self.writer.write(frame)
                async with asyncio.timeout(self._frame_timeout):
                    await self.writer.drain()
            except TimeoutError as exc:
                raise LockConnectionError("the peer stopped reading") from exc
            except OSError as exc:
                raise LockConnectionError(f"connection failed: {exc}") from exc

    async def receive(self, idle_timeout: float | None) -> dict[str, Any]:
        frame = await read_frame(
            self.reader,
            max_size=self._max_frame,
            idle_timeout=idle_timeout,
            frame_timeout=self._frame_timeout,
        )
        if len(frame) < MAC_BYTES:
            raise LockProtocolError("frame too short to carry a MAC")
        mac, body = frame[:MAC_BYTES], frame[MAC_BYTES:]
        counter = self._in_counter.to_bytes(8, "big")
        if not hmac.compare_digest(mac, _mac(self._key, self._in_label, counter, body)):
            raise LockAuthError("a frame failed authentication (tampered, replayed or reordered)")
        self._in_counter += 1
        return decode_message(body)

    async def close(self) -> None:
        await close_writer(self.writer)


async def close_writer(writer: asyncio.StreamWriter) -> None:
    """Close a stream, never raising and never waiting long on a dead peer."""
    writer.close()
    with contextlib.suppress(OSError, TimeoutError, asyncio.CancelledError):
        async with asyncio.timeout(1.0):
            await writer.wait_closed()


async def _send_plain(writer: asyncio.StreamWriter, message: dict[str, Any]) -> None:
    writer.write(encode_frame(encode_message(message)))
    await writer.drain()


async def _receive_plain(
    reader: asyncio.StreamReader, *, wait_s: float, max_frame: int
) -> dict[str, Any]:
    # Handshake frames are tiny; cap them well below the session limit.
    body = await read_frame(
        reader, max_size=min(max_frame, 4096), idle_timeout=wait_s, frame_timeout=wait_s
    )
    return decode_message(body)


def _field_bytes(message: dict[str, Any], name: str, size: int) -> bytes:
    value = message.get(name)
    try:
        raw = b64decode(value) if isinstance(value, str) else b""
    except (binascii.Error, ValueError):
        raw = b""
    if len(raw) != size:
        raise LockProtocolError(f"handshake field {name!r} is missing or malformed")
    return raw


async def server_handshake(
    reader: asyncio.StreamReader,
    writer: asyncio.StreamWriter,
    *,
    link_key: bytes,
    hello: Hello,
    handshake_s: float,
    max_frame: int = DEFAULT_MAX_FRAME,
    frame_timeout: float = 5.0,
) -> SecureChannel:
    """Authenticate a client within ``handshake_s`` seconds in all, or raise."""
    server_nonce = secrets.token_bytes(NONCE_BYTES)
    lock_id = hello.lock_id.encode()
    try:
        async with asyncio.timeout(handshake_s):
            await _send_plain(
                writer,
                {
                    "type": "hello",
                    "version": PROTOCOL_VERSION,
                    "lock_id": hello.lock_id,
                    "epoch": hello.epoch,
                    "nonce": b64encode(server_nonce),
                },
            )
            auth = await _receive_plain(reader, wait_s=handshake_s, max_frame=max_frame)
            if auth.get("type") != "auth" or auth.get("version") != PROTOCOL_VERSION:
                raise LockProtocolError("expected an auth frame of protocol version 1")
            client_nonce = _field_bytes(auth, "nonce", NONCE_BYTES)
            client_mac = _field_bytes(auth, "mac", MAC_BYTES)
            expected = _mac(link_key, b"client", lock_id, server_nonce, client_nonce)
            if not hmac.compare_digest(client_mac, expected):
                await _send_plain(writer, {"type": "auth_failed"})
                raise LockAuthError("a client failed the challenge (wrong shared key)")
            server_mac = _mac(link_key, b"server", lock_id, server_nonce, client_nonce)
            await _send_plain(writer, {"type": "auth_ok", "mac": b64encode(server_mac)})
    except TimeoutError as exc:
        raise LockConnectionError(f"handshake not completed within {handshake_s} s") from exc
    except OSError as exc:
        raise LockConnectionError(f"connection failed during the handshake: {exc}") from exc
    return SecureChannel(
        reader,
        writer,
        _mac(link_key, b"session", server_nonce, client_nonce),
        is_server=True,
        max_frame=max_frame,
        frame_timeout=frame_timeout,
    )


async def client_handshake(
    reader: asyncio.StreamReader,
    writer: asyncio.StreamWriter,
    *,
    link_key: bytes,
    handshake_s: float,
    expected_lock_id: str | None = None,
    max_frame: int = DEFAULT_MAX_FRAME,
    frame_timeout: float = 5.0,
) -> tuple[SecureChannel, Hello]:
    """Prove we hold the key, check that the lock does too, and return the channel."""
    try:
        async with asyncio.timeout(handshake_s):
            hello = await _receive_plain(reader, wait_s=handshake_s, max_frame=max_frame)
            if hello.get("type") != "hello" or hello.get("version") != PROTOCOL_VERSION:
                raise LockProtocolError("expected a hello frame of protocol version 1")
            lock_id, epoch = hello.get("lock_id"), hello.get("epoch")
            if not isinstance(lock_id, str) or not isinstance(epoch, str):
                raise LockProtocolError("hello frame lacks lock_id or epoch")
            if expected_lock_id is not None and lock_id != expected_lock_id:
                raise LockProtocolError(
                    f"connected to lock {lock_id!r}, expected {expected_lock_id!r}"
                )
            server_nonce = _field_bytes(hello, "nonce", NONCE_BYTES)
            client_nonce = secrets.token_bytes(NONCE_BYTES)
            lock_bytes = lock_id.encode()
            mac = _mac(link_key, b"client", lock_bytes, server_nonce, client_nonce)
            await _send_plain(
                writer,
                {
                    "type": "auth",
                    "version": PROTOCOL_VERSION,
                    "nonce": b64encode(client_nonce),
                    "mac": b64encode(mac),
                },
            )
            try:
                answer = await _receive_plain(reader, wait_s=handshake_s, max_frame=max_frame)
            except LockConnectionError as exc:
                raise LockAuthError("the lock hung up during the handshake") from exc
            if answer.get("type") == "auth_failed":
                raise LockAuthError("the lock refused our shared key")
            if answer.get("type") != "auth_ok":
                raise LockProtocolError("expected auth_ok or auth_failed")
            server_mac = _field_bytes(answer, "mac", MAC_BYTES)
            expected = _mac(link_key, b"server", lock_bytes, server_nonce, client_nonce)
            if not hmac.compare_digest(server_mac, expected):
                raise LockAuthError("the lock could not prove it holds the shared key")
    except TimeoutError as exc:
        raise LockConnectionError(f"handshake not completed within {handshake_s} s") from exc
    except OSError as exc:
        raise LockConnectionError(f"connection failed during the handshake: {exc}") from exc
    channel = SecureChannel(
        reader,
        writer,
        _mac(link_key, b"session", server_nonce, client_nonce),
        is_server=False,
        max_frame=max_frame,
        frame_timeout=frame_timeout,
    )
    return channel, Hello(lock_id=lock_id, epoch=epoch)
