"""Typed answers from any ``ChatModel``: the schema sent with a request, the JSON pulled out of
what the model wrote, validation with the error fed back.

Pure functions over the model port (:mod:`assistantx.core.ports.model`): agents use them
without knowing which provider answers, and providers use the schema helpers to send the
schema the way their server accepts.
"""

from assistantx.core.structured._json_extract import extract_json_object
from assistantx.core.structured.call import (
    Attempt,
    StructuredResult,
    describe_validation_error,
    parse_output,
    structured_call,
)
from assistantx.core.structured.schema import grammar_schema, schema_outline

__all__ = [
    "Attempt",
    "StructuredResult",
    "describe_validation_error",
    "extract_json_object",
    "grammar_schema",
    "parse_output",
    "schema_outline",
    "structured_call",
]
