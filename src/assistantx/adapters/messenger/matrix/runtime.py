"""Building the Matrix messenger from settings, for the service (or any other host process).

``ASSISTANTX_MESSENGER=matrix`` selects it and ``ASSISTANTX_MATRIX_CONFIG`` names its YAML file
(see ``config.py``); the inbound event store is ``ASSISTANTX_MATRIX_STORE`` or
``DATA_DIR/matrix.sqlite3``. The service (``assistantx.service.matrix_wiring``) builds it in
its composition root, in this order::

    setup = matrix_setup(settings)                 # at create_app: fails fast on a bad config
    ...                                            # the runtime's start: the journal is open
    runtime = setup.build(transcript=journal)      # nothing connects yet
    assistant = Assistant(AssistantParts(messenger=runtime.messenger, ...))
    await assistant.start()                        # connects its inbox to the messenger
    await runtime.messenger.start()                # replays unhandled messages, starts /sync
    app.include_router(runtime.push_router)        # push endpoints: /_matrix/app/v1/...
    ...
    await assistant.stop()
    await runtime.aclose()                         # stops the messenger (its HTTP client),
                                                   # closes the store; also after a failure

The messenger is started after the consumer's inbox is connected: it replays what a previous
run accepted but never acknowledged, and a push that arrives before then is answered 500, so
the homeserver retries it later instead of losing it.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from pathlib import Path

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
        """Stop the messenger (it closes its HTTP client), then close its store, also when
        stopping fails; idempotent."""
        try:
            await self.messenger.stop()
        finally:
            await self.store.close()


@dataclass(frozen=True)
class MatrixSetup:
    """What the settings say of the Matrix messenger, checked; ``build`` makes it."""

    config: MatrixConfig
    store_path: Path
    database_url: str | None = field(default=None, repr=False)  # holds a password

    def build(self, *, transcript: Transcript | None = None) -> MatrixRuntime:
        store = SqliteEventStore(self.store_path, database_url=self.database_url)
        return matrix_runtime(self.config, store, transcript=transcript)


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
    return matrix_setup(settings).build(transcript=transcript)


def matrix_setup(settings: Settings) -> MatrixSetup:
    """The Matrix config the settings name, loaded and checked (nothing is opened yet);
    ``MessengerError`` when they name none or a bad one."""
    if settings.messenger != "matrix":
        raise MessengerError(
            f"ASSISTANTX_MESSENGER is {settings.messenger!r}; the Matrix messenger needs 'matrix'"
        )
    if settings.matrix_config is None:
        raise MessengerError("ASSISTANTX_MESSENGER=matrix needs ASSISTANTX_MATRIX_CONFIG (a YAML)")
    config = load_matrix_config(settings.matrix_config)
    # With ASSISTANTX_DATABASE_URL the bot's state goes to the journal's PostgreSQL.
    return MatrixSetup(
        config,
        settings.matrix_store or settings.data_dir / DEFAULT_STORE_NAME,
        database_url=settings.database,
    )
