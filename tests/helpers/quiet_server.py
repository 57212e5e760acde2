"""A uvicorn server for the fakes a test runs in its own event loop (a scripted model, a
scripted homeserver, a bare ASGI app): no signal handling (a test must not take over
SIGINT), and a stop that takes milliseconds, not uvicorn's 0.1 s tick plus its fixed 0.1 s
sleep. The service's own server (``assistantx.service.server``) runs in the tests with this
timing too (``helpers.servers.serving_app``), its own stop otherwise unchanged; the tests of
how the service stops as a process start it as one (``service.server.serve``)."""

from __future__ import annotations

import asyncio
import contextlib
import socket
from collections.abc import Generator

import uvicorn


class QuietServer(uvicorn.Server):
    """uvicorn without signal handling (a test must not take over SIGINT) that stops as soon
    as asked instead of on its next 0.1 s tick."""

    def __init__(self, config: uvicorn.Config) -> None:
        super().__init__(config)
        self.exit_requested = asyncio.Event()

    @contextlib.contextmanager
    def capture_signals(self) -> Generator[None, None, None]:
        yield

    async def main_loop(self) -> None:
        await self.on_tick(0)  # sets the default response headers
        await self.exit_requested.wait()

    async def shutdown(self, sockets: list[socket.socket] | None = None) -> None:
        """uvicorn's shutdown, less its fixed 0.1 s sleep after asking the connections to
        close (the tests start and stop a scripted model hundreds of times): it waits only
        while a connection or task is still open, up to the graceful-shutdown timeout;
        then, as uvicorn does, cancels what is left."""
        for server in self.servers:
            server.close()
        for sock in sockets or []:
            sock.close()
        for connection in list(self.server_state.connections):
            connection.shutdown()
        state = self.server_state
        # uvicorn waits without a bound when no graceful-shutdown timeout is set; a test's
        # fake gets 30 s. uvicorn has no event for "the last connection closed": checked
        # every 5 ms.
        limit_s = self.config.timeout_graceful_shutdown
        for _ in range(int((30 if limit_s is None else limit_s) / 0.005)):
            if not (state.connections or state.tasks):
                break
            await asyncio.sleep(0.005)
        for task in state.tasks:
            task.cancel(msg="the scripted model stopped")
        for server in self.servers:
            await server.wait_closed()
        await self.lifespan.shutdown()

    def request_exit(self) -> None:
        self.should_exit = True
        self.exit_requested.set()
