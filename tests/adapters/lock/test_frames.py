"""The frame parser: whole frames out of any chunking, clear errors on anything else."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assistantx.adapters.lock.protocol.frames import (
    FrameDecoder,
    decode_message,
    encode_frame,
    encode_message,
)
from assistantx.core.errors import LockProtocolError

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
