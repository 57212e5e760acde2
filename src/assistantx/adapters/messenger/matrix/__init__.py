"""The Matrix messenger: application-service push, /sync pull, or both."""

from assistantx.adapters.messenger.matrix.adapter import MatrixMessenger, transaction_id
from assistantx.adapters.messenger.matrix.appservice import create_appservice_router
from assistantx.adapters.messenger.matrix.client import MatrixClient, MatrixError
from assistantx.adapters.messenger.matrix.config import MatrixConfig, load_matrix_config
from assistantx.adapters.messenger.matrix.ingest import EventIngestor
from assistantx.adapters.messenger.matrix.normalize import EventNormalizer
from assistantx.adapters.messenger.matrix.registration import registration, write_registration
from assistantx.adapters.messenger.matrix.runtime import (
    MatrixRuntime,
    MatrixSetup,
    build_matrix_runtime,
    matrix_runtime,
    matrix_setup,
)
from assistantx.adapters.messenger.matrix.store import EventStore, SqliteEventStore
from assistantx.adapters.messenger.matrix.sync import SyncPoller
from assistantx.core.http_retry import RetryPolicy

__all__ = [
    "EventIngestor",
    "EventNormalizer",
    "EventStore",
    "MatrixClient",
    "MatrixConfig",
    "MatrixError",
    "MatrixMessenger",
    "MatrixRuntime",
    "MatrixSetup",
    "RetryPolicy",
    "SqliteEventStore",
    "SyncPoller",
    "build_matrix_runtime",
    "create_appservice_router",
    "load_matrix_config",
    "matrix_runtime",
    "matrix_setup",
    "registration",
    "transaction_id",
    "write_registration",
]
