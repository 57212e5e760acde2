"""Reading a request body with a size cap, before anything parses it."""

from __future__ import annotations

from starlette.requests import Request


class BodyTooLargeError(Exception):
    """The body is longer than the endpoint accepts (answered with 413)."""


async def read_capped_body(request: Request, limit_bytes: int) -> bytes:
    """The raw body, or ``BodyTooLargeError`` as soon as it passes ``limit_bytes``.

    A declared Content-Length over the limit is refused without reading; otherwise the
    stream is read chunk by chunk, so a lying or chunked sender cannot make us buffer more.
    """
    declared = request.headers.get("content-length")
    if declared is not None and declared.isdigit() and int(declared) > limit_bytes:
        raise BodyTooLargeError(f"body of {declared} bytes exceeds {limit_bytes}")
    chunks: list[bytes] = []
    size = 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > limit_bytes:
            raise BodyTooLargeError(f"body exceeds {limit_bytes} bytes")
        chunks.append(chunk)
    return b"".join(chunks)
