"""The JSON schemas we send to a server, kept inside what grammar-based servers accept.

Pydantic's schema of an output model is the full truth, but servers that enforce a schema by
compiling it to a grammar (llama.cpp, Ollama, vLLM's guided decoding) choke on parts of it:

- ``maxLength: 2000`` becomes two thousand repetitions of a character rule; llama.cpp's
  converter builds them and its server has crashed on it. Length limits therefore stay in the
  pydantic validators (an over-long answer is rejected and repaired) and leave the grammar;
  so do ``maxItems`` above :data:`MAX_ITEMS_IN_GRAMMAR`.
- A discriminated union member whose discriminator (``type`` of an action, ``kind`` of a
  memory update) has a default is not ``required``; a grammar then lets the model omit it
  and every such object reads as the first member. Discriminators are made required.
- ``discriminator``/``mapping``, ``title``, ``default`` and ``examples`` mean nothing to a
  grammar and only lengthen the request; they are dropped (descriptions stay: they guide).

:func:`grammar_schema` does that conversion; :func:`schema_outline` is the one-line form of
the same shape that a prompt carries when the server enforces the schema itself.
"""

from __future__ import annotations

import copy
import json
from typing import Any

from pydantic import BaseModel

MAX_ITEMS_IN_GRAMMAR = 8
_DROPPED_KEYS = frozenset({"title", "default", "examples", "discriminator"})


def grammar_schema(model: type[BaseModel]) -> dict[str, Any]:
    """``model``'s JSON schema made safe for grammar-based structured output."""
    schema = copy.deepcopy(model.model_json_schema())
    _discriminators_required(schema)
    return _strip(schema)  # type: ignore[no-any-return]


def _discriminators_required(schema: dict[str, Any]) -> None:
    """Every property with a ``const`` value (a union tag) becomes required."""
    for definition in [schema, *schema.get("$defs", {}).values()]:
        properties = definition.get("properties")
        if not isinstance(properties, dict):
            continue
        tags = [name for name, prop in properties.items() if "const" in prop]
        if tags:
            required = list(definition.get("required", []))
            definition["required"] = [*tags, *(r for r in required if r not in tags)]


def _strip(node: Any) -> Any:
    if isinstance(node, list):
        return [_strip(item) for item in node]
    if not isinstance(node, dict):
        return node
    out: dict[str, Any] = {}
    for key, value in node.items():
        if key == "properties" and isinstance(value, dict):
            # property names are data here, never keywords to drop
            out[key] = {name: _strip(prop) for name, prop in value.items()}
            continue
        if key in _DROPPED_KEYS or key == "maxLength":
            continue
        if key == "maxItems" and isinstance(value, int) and value > MAX_ITEMS_IN_GRAMMAR:
            continue
        out[key] = _strip(value)
    return out


def schema_outline(model: type[BaseModel]) -> str:
    """A compact one-object sketch of ``model``'s shape (field names and kinds), for prompts
    whose schema the server enforces; the full schema would cost a thousand tokens more."""
    schema = grammar_schema(model)
    defs = schema.get("$defs", {})
    return json.dumps(_outline(schema, defs), separators=(",", ":"))


def _outline(node: dict[str, Any], defs: dict[str, Any]) -> Any:
    if "$ref" in node:
        return _outline(defs[node["$ref"].rsplit("/", 1)[-1]], defs)
    if "const" in node:
        return node["const"]
    for key in ("oneOf", "anyOf"):
        if key in node:
            options = [_outline(option, defs) for option in node[key]]
            options = [o for o in options if o != "null"]
            return options[0] if len(options) == 1 else {"one of": options}
    if "enum" in node:
        return "|".join(str(v) for v in node["enum"])
    kind = node.get("type")
    if kind == "object":
        required = set(node.get("required", []))
        return {
            (name if name in required else f"{name}?"): _outline(prop, defs)
            for name, prop in node.get("properties", {}).items()
        }
    if kind == "array":
        return [_outline(node.get("items", {}), defs)]
    return kind if isinstance(kind, str) else "any"
