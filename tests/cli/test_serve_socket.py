"""The socket `serve` listens on: connections it accepts send small writes at once."""

from __future__ import annotations

import asyncio
import socket

from assistantx.cli.serve_cmd import _bind


async def _accepted_nodelay(listener: socket.socket) -> int:
    """TCP_NODELAY of the server side of one connection asyncio accepts on ``listener``."""
    seen: asyncio.Future[int] = asyncio.get_running_loop().create_future()

    async def on_connect(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        sock = writer.get_extra_info("socket")
        seen.set_result(sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY))
        writer.close()

    server = await asyncio.start_server(on_connect, sock=listener)
    async with server:
        port = listener.getsockname()[1]
        _, writer = await asyncio.open_connection("127.0.0.1", port)
        nodelay = await asyncio.wait_for(seen, 10)
        writer.close()
    return nodelay


def test_accepted_connections_have_nagle_off() -> None:
    # With Nagle on, a kept-alive response written as headers then body waits for the
    # client's delayed ACK: ~40 ms added to every request on a reused connection.
    listener = _bind("127.0.0.1", 0)
    assert asyncio.run(_accepted_nodelay(listener)) != 0
