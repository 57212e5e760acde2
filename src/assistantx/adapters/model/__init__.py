"""Language models behind one interface.

Agents depend on :class:`ChatModel`, :class:`ChatRequest` and :func:`structured_call` only;
the app picks a provider (``OpenAICompatibleModel`` for any OpenAI-compatible server) and
wraps it in a :class:`MeteredModel` so every call lands in a :class:`UsageLedger`.
"""

from assistantx.adapters.model._json_extract import extract_json_object
from assistantx.adapters.model._retry import RetryPolicy, parse_retry_after
from assistantx.adapters.model.openai_compat import OpenAICompatibleModel, estimate_tokens
from assistantx.adapters.model.structured import (
    Attempt,
    StructuredResult,
    describe_validation_error,
    parse_output,
    structured_call,
)
from assistantx.adapters.model.usage import CallRecord, MeteredModel, UsageLedger, UsageTotals
from assistantx.core.ports.model import (
    ChatModel,
    ChatRequest,
    ChatResponse,
    Message,
    Role,
    StructuredMode,
    Usage,
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
    "parse_output",
    "parse_retry_after",
    "structured_call",
]
