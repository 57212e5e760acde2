"""A TCP proxy on 127.0.0.1 that can cut, refuse or silently swallow connections: the
network faults a lock link must survive, made on demand."""

from __future__ import annotations

import asyncio
import contextlib


class _Pipe:
    def __init__(self, client: asyncio.StreamWriter, upstream: asyncio.StreamWriter) -> None:
        self.writers = (client, upstream)
        self.swallowing = False
        self.tasks: list[asyncio.Task[None]] = []


class FaultyProxy:
    def __init__(self, target_port: int) -> None:
        self.target_port = target_port
        self.refusing = False
        self._pipes: set[_Pipe] = set()
        self._server: asyncio.Server | None = None
        self.accepted = 0

    async def start(self) -> int:
        self._server = await asyncio.start_server(self._accept, "127.0.0.1", 0)
        return int(self._server.sockets[0].getsockname()[1])

    async def stop(self) -> None:
        self.cut()
        for pipe in list(self._pipes):
            await asyncio.gather(*pipe.tasks, return_exceptions=True)
        if self._server is not None:
            self._server.close()
            await self._server.wait_closed()

    def cut(self) -> None:
        """Reset every open connection, as a failing switch would."""
        for pipe in self._pipes:
            for writer in pipe.writers:
                writer.transport.abort()

    def swallow(self) -> None:
        """Keep open connections up but deliver nothing more: a half-open link."""
        for pipe in self._pipes:
            pipe.swallowing = True

    async def _accept(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        if self.refusing:
            writer.transport.abort()
            return
        self.accepted += 1
        up_reader, up_writer = await asyncio.open_connection("127.0.0.1", self.target_port)
        pipe = _Pipe(writer, up_writer)
        self._pipes.add(pipe)
        pipe.tasks = [
            asyncio.create_task(self._pump(reader, up_writer, pipe)),
            asyncio.create_task(self._pump(up_reader, writer, pipe)),
        ]
        await asyncio.gather(*pipe.tasks, return_exceptions=True)
        self._pipes.discard(pipe)
        for w in pipe.writers:
            w.transport.abort()

    async def _pump(
        self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter, pipe: _Pipe
    ) -> None:
        with contextlib.suppress(OSError):
            while data := await reader.read(65536):
                if not pipe.swallowing:
                    writer.write(data)
                    await writer.drain()
        for w in pipe.writers:
            if not pipe.swallowing:
                w.transport.abort()
