"""The frame parser: whole frames out of any chunking, clear errors on anything else."""

from __future__ import annotations

import asyncio

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assistantx.adapters.lock.protocol.frames import (
    FrameDecoder,
    decode_message,
    encode_frame,
    encode_message,
    read_frame,
)
from assistantx.core.errors import LockError, LockProtocolError

bounded = settings(max_examples=200, deadline=None, derandomize=True)


@bounded
@given(
    st.lists(st.binary(max_size=300), max_size=8),
    st.lists(st.integers(min_value=1, max_value=64), min_size=1, max_size=20),
)
def test_frames_survive_any_chunking(bodies: list[bytes], cuts: list[int]) -> None:
    stream = b"".join(encode_frame(body, 512) for body in bodies)
    decoder = FrameDecoder(max_size=512)
    out: list[bytes] = []
    position, index = 0, 0
    while position < len(stream):
        size = cuts[index % len(cuts)]
        out += decoder.feed(stream[position : position + size])
        position += size
        index += 1
    assert out == bodies
    assert decoder.pending == 0


@bounded
@given(st.binary(max_size=2000))
def test_fuzz_the_parser_yields_frames_or_a_protocol_error(data: bytes) -> None:
    decoder = FrameDecoder(max_size=256)
    if _announces_oversized_frame(data, 256):
        with pytest.raises(LockProtocolError, match="limit"):
            decoder.feed(data)
        return
    for body in decoder.feed(data):
        assert len(body) <= 256
        try:
            assert isinstance(decode_message(body), dict)
        except LockProtocolError:
            pass


def _announces_oversized_frame(stream: bytes, limit: int) -> bool:
    position = 0
    while position + 4 <= len(stream):
        length = int.from_bytes(stream[position : position + 4], "big")
        if length > limit:
            return True
        position += 4 + length
    return False


def test_an_oversized_frame_is_refused_before_its_body_arrives() -> None:
    decoder = FrameDecoder(max_size=1024)
    with pytest.raises(LockProtocolError, match=r"limit (of|is) 1024"):
        decoder.feed((1025).to_bytes(4, "big"))
    with pytest.raises(LockProtocolError):
        encode_frame(b"x" * 1025, 1024)


@pytest.mark.parametrize("body", [b"", b"[1,2]", b'"text"', b"\xff", b"{", b"[" * 100_000])
def test_only_json_objects_are_messages(body: bytes) -> None:
    with pytest.raises(LockProtocolError):
        decode_message(body)


def test_messages_round_trip() -> None:
    message = {"id": 1, "op": "scan", "payload": "abc", "nested": {"é": [1.5, None]}}
    assert decode_message(encode_message(message)) == message


# JSON values as the link carries them (finite numbers: JSON has no NaN or infinity).
_json = st.recursive(
    st.none()
    | st.booleans()
    | st.integers(min_value=-(2**53), max_value=2**53)
    | st.floats(allow_nan=False, allow_infinity=False)
    | st.text(max_size=40),
    lambda inner: (
        st.lists(inner, max_size=5) | st.dictionaries(st.text(max_size=10), inner, max_size=5)
    ),
    max_leaves=8,
)
_messages = st.dictionaries(st.text(max_size=12), _json, max_size=6)


@settings(max_examples=60, deadline=None, derandomize=True)
@given(st.lists(_messages, max_size=3), st.integers(min_value=1, max_value=50))
def test_any_messages_round_trip_through_frames(
    messages: list[dict[str, object]], chunk: int
) -> None:
    stream = b"".join(encode_frame(encode_message(m)) for m in messages)
    decoder = FrameDecoder()
    bodies: list[bytes] = []
    for start in range(0, len(stream), chunk):
        bodies += decoder.feed(stream[start : start + chunk])
    assert [decode_message(b) for b in bodies] == messages


@bounded
@given(st.binary(max_size=500))
def test_any_body_is_a_message_or_a_protocol_error(body: bytes) -> None:
    try:
        message = decode_message(body)
    except LockProtocolError:
        return
    assert isinstance(message, dict)


@bounded
@given(st.binary(max_size=600))
def test_the_stream_reader_yields_frames_or_a_lock_error(data: bytes) -> None:
    """``read_frame`` over arbitrary bytes then end of stream: bodies within the limit, then
    a ``LockError`` (closed mid-frame, oversized); never another exception."""

    async def read_all() -> list[bytes]:
        reader = asyncio.StreamReader()
        reader.feed_data(data)
        reader.feed_eof()
        bodies: list[bytes] = []
        while True:
            try:
                bodies.append(
                    await read_frame(reader, max_size=256, idle_timeout=1.0, frame_timeout=1.0)
                )
            except LockError:
                return bodies

    bodies = asyncio.run(read_all())
    assert all(len(b) <= 256 for b in bodies)
    assert b"".join(encode_frame(b, 256) for b in bodies) == data[: sum(4 + len(b) for b in bodies)]
