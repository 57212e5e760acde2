"""The Matrix messenger: application-service push, /sync pull, or both.

The names below load their module on first use: the service imports the push route's body
limit from ``appservice`` at every start, and a service that does not talk on Matrix should
not pay for the HTTP client and the rest (PEP 562's module ``__getattr__``)."""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

# Loaded now: the function ``registration`` shares its name with its module, which importing
# the module would bind here in its place (config and yaml; the service loads both anyway).
from assistantx.adapters.messenger.matrix.registration import registration, write_registration

if TYPE_CHECKING:
    from assistantx.adapters.messenger.matrix.adapter import MatrixMessenger, transaction_id
    from assistantx.adapters.messenger.matrix.appservice import create_appservice_router
    from assistantx.adapters.messenger.matrix.client import MatrixClient, MatrixError
    from assistantx.adapters.messenger.matrix.config import MatrixConfig, load_matrix_config
    from assistantx.adapters.messenger.matrix.ingest import EventIngestor
    from assistantx.adapters.messenger.matrix.normalize import EventNormalizer
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

_HOMES = {
    "MatrixMessenger": "adapter",
    "transaction_id": "adapter",
    "create_appservice_router": "appservice",
    "MatrixClient": "client",
    "MatrixError": "client",
    "MatrixConfig": "config",
    "load_matrix_config": "config",
    "EventIngestor": "ingest",
    "EventNormalizer": "normalize",
    "MatrixRuntime": "runtime",
    "MatrixSetup": "runtime",
    "build_matrix_runtime": "runtime",
    "matrix_runtime": "runtime",
    "matrix_setup": "runtime",
    "EventStore": "store",
    "SqliteEventStore": "store",
    "SyncPoller": "sync",
}

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


def __getattr__(name: str) -> Any:
    if name == "RetryPolicy":
        from assistantx.core.http_retry import RetryPolicy

        return RetryPolicy
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f"{__name__}.{home}"), name)
