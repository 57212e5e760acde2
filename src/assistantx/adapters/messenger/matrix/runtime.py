"""Building the Matrix messenger from settings, for the service (or any other host process).

``ASSISTANTX_MESSENGER=matrix`` selects it and ``ASSISTANTX_MATRIX_CONFIG`` names its YAML file
(see ``config.py``); the inbound event store is ``ASSISTANTX_MATRIX_STORE`` or
``DATA_DIR/matrix.sqlite3``. The service (``assistantx.service.runtime``) wires it like this::

    runtime = build_matrix_runtime(settings)       # fails fast on a bad or missing config
    if runtime.router is not None:
        app.include_router(runtime.router)         # push endpoints: /_matrix/app/v1/...
    assistant = Assistant(AssistantParts(messenger=runtime.messenger, ...))
    await assistant.start()                        # connects its inbox to the messenger
    await runtime.messenger.start()                # replays unhandled messages, starts /sync
    ...
    await assistant.stop()
    await runtime.aclose()                         # stops the messenger, closes the store

The messenger is started after the consumer's inbox is connected: it replays what a previous
run accepted but never acknowledged, and a push that arrives before then is answered 500, so
the homeserver retries it later instead of losing it.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

from fastapi import APIRouter

from assistantx.adapters.messenger.matrix.adapter import MatrixMessenger, Transcript
from assistantx.adapters.messenger.matrix.config import MatrixConfig, load_matrix_config
from assistantx.adapters.messenger.matrix.store import EventStore, SqliteEventStore
from assistantx.core.errors import MessengerError
from assistantx.core.settings import Settings

logger = logging.getLogger(__name__)

DEFAULT_STORE_NAME = "matrix.sqlite3"


@dataclass(frozen=True)
class MatrixRuntime:
    """The messenger, the push router to mount (None in pull mode) and the store they share.

    In pull mode ``push_router`` still answers a registration left from push mode (it
    acknowledges and drops), so the homeserver never retries pushes against a 405."""

    messenger: MatrixMessenger
    router: APIRouter | None
    store: EventStore

    @property
    def push_router(self) -> APIRouter:
        """What to mount at the appservice URL whatever the mode."""
        return self.router or self.messenger.leftover_push_router()

    def closing(self) -> None:
        """The service is shutting down: nothing more is sent (running instructions resume
        after the restart rather than telling people they failed)."""
        self.messenger.closing = True

    @property
    def config(self) -> MatrixConfig:
        return self.messenger.config

    async def aclose(self) -> None:
        """Stop the messenger, then close its store; idempotent."""
        await self.messenger.stop()
        await self.store.close()


def matrix_runtime(
    config: MatrixConfig, store: EventStore, *, transcript: Transcript | None = None
) -> MatrixRuntime:
    """The messenger for ``config`` over ``store`` (not started; the runtime owns the store);
    every message in and out is also written to ``transcript`` (the service's journal)."""
    messenger = MatrixMessenger(config, store, transcript=transcript)
    router = messenger.appservice_router() if config.push_enabled else None
    logger.info(
        "Matrix messenger on %s as %s, mode %s, %d people, %d groups",
        config.homeserver_url,
        config.bot_user_id if config.push_enabled else config.pull_user_id,
        config.mode,
        len(config.people),
        len(config.groups),
    )
    return MatrixRuntime(messenger=messenger, router=router, store=store)


def build_matrix_runtime(
    settings: Settings, *, transcript: Transcript | None = None
) -> MatrixRuntime:
    """The Matrix messenger the settings describe; ``MessengerError`` when they do not."""
    if settings.messenger != "matrix":
        raise MessengerError(
            f"ASSISTANTX_MESSENGER is {settings.messenger!r}; the Matrix messenger needs 'matrix'"
        )
    if settings.matrix_config is None:
        raise MessengerError("ASSISTANTX_MESSENGER=matrix needs ASSISTANTX_MATRIX_CONFIG (a YAML)")
    config = load_matrix_config(settings.matrix_config)
    store_path = settings.matrix_store or settings.data_dir / DEFAULT_STORE_NAME
    # With ASSISTANTX_DATABASE_URL the bot's state goes to the journal's PostgreSQL.
    store = SqliteEventStore(store_path, database_url=settings.database)
    return matrix_runtime(config, store, transcript=transcript)
