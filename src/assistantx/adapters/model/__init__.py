"""Language models behind one interface.

Agents depend on the port (:mod:`assistantx.core.ports.model`) and the pure structured-output
helpers (:mod:`assistantx.core.structured`, re-exported here) only, never on this package. The
composition root (service, CLI, bench) picks a provider (``model_from_settings``:
``OpenAICompatibleModel`` for any OpenAI-compatible server) and injects it; wrapped in a
:class:`MeteredModel`, every call lands in a :class:`UsageLedger`.

Each name loads its module on first use (PEP 562): the service imports
``model_from_settings`` at every start and needs no HTTP client without a model URL.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from assistantx.core.lazy import exports

if TYPE_CHECKING:
    from assistantx.adapters.model.configured import model_from_settings
    from assistantx.adapters.model.openai_compat import OpenAICompatibleModel, estimate_tokens
    from assistantx.adapters.model.usage import CallRecord, MeteredModel, UsageLedger, UsageTotals
    from assistantx.core.http_retry import RetryPolicy, parse_retry_after
    from assistantx.core.ports.model import (
        ChatModel,
        ChatRequest,
        ChatResponse,
        Message,
        Role,
        StructuredMode,
        Usage,
    )
    from assistantx.core.structured import (
        Attempt,
        StructuredResult,
        describe_validation_error,
        extract_json_object,
        parse_output,
        structured_call,
    )

_HOMES = {
    "model_from_settings": "assistantx.adapters.model.configured",
    "OpenAICompatibleModel": "assistantx.adapters.model.openai_compat",
    "estimate_tokens": "assistantx.adapters.model.openai_compat",
    "CallRecord": "assistantx.adapters.model.usage",
    "MeteredModel": "assistantx.adapters.model.usage",
    "UsageLedger": "assistantx.adapters.model.usage",
    "UsageTotals": "assistantx.adapters.model.usage",
    "RetryPolicy": "assistantx.core.http_retry",
    "parse_retry_after": "assistantx.core.http_retry",
    "ChatModel": "assistantx.core.ports.model",
    "ChatRequest": "assistantx.core.ports.model",
    "ChatResponse": "assistantx.core.ports.model",
    "Message": "assistantx.core.ports.model",
    "Role": "assistantx.core.ports.model",
    "StructuredMode": "assistantx.core.ports.model",
    "Usage": "assistantx.core.ports.model",
    "Attempt": "assistantx.core.structured",
    "StructuredResult": "assistantx.core.structured",
    "describe_validation_error": "assistantx.core.structured",
    "extract_json_object": "assistantx.core.structured",
    "parse_output": "assistantx.core.structured",
    "structured_call": "assistantx.core.structured",
}

__all__ = [
    "Attempt",
    "CallRecord",
    "ChatModel",
    "ChatRequest",
    "ChatResponse",
    "Message",
    "MeteredModel",
    "OpenAICompatibleModel",
    "RetryPolicy",
    "Role",
    "StructuredMode",
    "StructuredResult",
    "Usage",
    "UsageLedger",
    "UsageTotals",
    "describe_validation_error",
    "estimate_tokens",
    "extract_json_object",
    "model_from_settings",
    "parse_output",
    "parse_retry_after",
    "structured_call",
]


__getattr__ = exports(__name__, _HOMES)
