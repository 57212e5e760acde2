"""Language models behind one interface.

Agents depend on the port (:mod:`assistantx.core.ports.model`) and the pure structured-output
helpers (:mod:`assistantx.core.structured`, re-exported here) only, never on this package. The
composition root (service, CLI, bench) picks a provider (``model_from_settings``:
``OpenAICompatibleModel`` for any OpenAI-compatible server) and injects it; wrapped in a
:class:`MeteredModel`, every call lands in a :class:`UsageLedger`.
"""

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
