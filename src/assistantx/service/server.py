"""uvicorn's server for the service, with a stop that does not wait on live event streams.

On SIGTERM/SIGINT uvicorn stops accepting, then waits for open connections to finish before
it runs the app's lifespan shutdown. An SSE stream never finishes by itself, so the hub is
closed first: every stream ends (clients reconnect with Last-Event-ID to the next server)
and its connection closes. ``timeout_graceful_shutdown`` bounds any other slow request.
"""

from __future__ import annotations

import socket

import uvicorn
from fastapi import FastAPI

from assistantx.service.offices.directory import Offices

GRACEFUL_SHUTDOWN_S = 2  # seconds (uvicorn takes an int)


class ServiceServer(uvicorn.Server):
    def __init__(self, config: uvicorn.Config, offices: Offices) -> None:
        super().__init__(config)
        self.offices = offices

    async def shutdown(self, sockets: list[socket.socket] | None = None) -> None:
        self.offices.close_streams()  # the live streams end before uvicorn waits for them
        await super().shutdown(sockets)


KEEP_ALIVE_S = 75


def service_server(app: FastAPI, host: str, port: int, *, log_level: str = "info") -> ServiceServer:
    """The server for an app made by ``create_app``."""
    config = uvicorn.Config(
        app,
        host=host,
        port=port,
        log_level=log_level,
        access_log=False,
        timeout_graceful_shutdown=GRACEFUL_SHUTDOWN_S,
        # An idle connection is closed by the server only well after any client or proxy in
        # front would have dropped it (60 s is the common proxy default): with uvicorn's 5 s,
        # a request sent as the server closed its connection failed with a read error (seen
        # after the event loop was held for 5.3 s under load).
        timeout_keep_alive=KEEP_ALIVE_S,
    )
    offices: Offices = app.state.offices
    return ServiceServer(config, offices)
