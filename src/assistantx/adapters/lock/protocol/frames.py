"""Framing of the lock link: a 4-byte big-endian length, then that many bytes.

During the handshake a frame body is a JSON object; afterwards it is a 32-byte MAC followed
by a JSON object (see ``link``). A declared length above ``max_size`` is refused before any
byte of the body is read, so a hostile peer cannot make either side buffer much.

``FrameDecoder`` is the sans-I/O parser (fed arbitrary chunks; fuzzed in the tests);
``read_frame`` is the asyncio reader with timeouts for slow or silent peers.
"""

from __future__ import annotations

import asyncio
import json
import struct
from typing import Any

from assistantx.core.errors import LockConnectionError, LockProtocolError, LockTimeoutError

HEADER = struct.Struct(">I")
DEFAULT_MAX_FRAME = 64 * 1024


def encode_frame(body: bytes, max_size: int = DEFAULT_MAX_FRAME) -> bytes:
    if len(body) > max_size:
        raise LockProtocolError(f"frame of {len(body)} bytes exceeds the limit of {max_size}")
    return HEADER.pack(len(body)) + body


class FrameDecoder:
    """Splits a byte stream into frame bodies; raises ``LockProtocolError`` on an oversized
    frame, after which the stream cannot be resynchronised and must be closed."""

    def __init__(self, max_size: int = DEFAULT_MAX_FRAME) -> None:
        self.max_size = max_size
        self._buffer = bytearray()

    def feed(self, data: bytes) -> list[bytes]:
        self._buffer += data
        frames: list[bytes] = []
        while len(self._buffer) >= HEADER.size:
            (length,) = HEADER.unpack_from(self._buffer)
            if length > self.max_size:
                raise LockProtocolError(
                    f"peer announced a {length}-byte frame; the limit is {self.max_size}"
                )
            end = HEADER.size + length
            if len(self._buffer) < end:
                break
            frames.append(bytes(self._buffer[HEADER.size : end]))
            del self._buffer[:end]
        return frames

    @property
    def pending(self) -> int:
        """Bytes received that do not yet form a whole frame."""
        return len(self._buffer)


async def read_frame(
    reader: asyncio.StreamReader,
    *,
    max_size: int = DEFAULT_MAX_FRAME,
    idle_timeout: float | None,
    frame_timeout: float,
) -> bytes:
    """Read one frame body.

    ``idle_timeout`` bounds the wait for a frame to begin (None: wait for ever);
    ``frame_timeout`` bounds the time from its first byte to its last, so a peer trickling
    a byte a second (slowloris) is cut off.
    """
    try:
        async with asyncio.timeout(idle_timeout):
            first = await reader.readexactly(1)
    except TimeoutError as exc:
        raise LockTimeoutError(f"no frame within {idle_timeout} s") from exc
    except asyncio.IncompleteReadError as exc:
        raise LockConnectionError("the peer closed the connection") from exc
    except OSError as exc:
        raise LockConnectionError(f"connection failed: {exc}") from exc
    try:
        async with asyncio.timeout(frame_timeout):
            header = first + await reader.readexactly(HEADER.size - 1)
            (length,) = HEADER.unpack(header)
            if length > max_size:
                raise LockProtocolError(
                    f"peer announced a {length}-byte frame; the limit is {max_size}"
                )
            return await reader.readexactly(length)
    except TimeoutError as exc:
        raise LockTimeoutError(f"frame not completed within {frame_timeout} s") from exc
    except asyncio.IncompleteReadError as exc:
        raise LockConnectionError("the peer closed the connection mid-frame") from exc
    except OSError as exc:
        raise LockConnectionError(f"connection failed: {exc}") from exc


def encode_message(message: dict[str, Any]) -> bytes:
    return json.dumps(message, separators=(",", ":"), ensure_ascii=False).encode("utf-8")


def decode_message(body: bytes) -> dict[str, Any]:
    """Parse a JSON object; anything else is a ``LockProtocolError``."""
    try:
        message = json.loads(body.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError, RecursionError) as exc:
        raise LockProtocolError("frame is not UTF-8 JSON") from exc
    if not isinstance(message, dict):
        raise LockProtocolError("frame is not a JSON object")
    return message
