"""Find the JSON object in what a language model wrote.

Models wrap JSON in code fences, put prose before and after it, think aloud in
``<think>...</think>`` first, leave a trailing comma, or write a raw line break inside a
string. This module tries, in order: the whole text, each fenced block, then each top-level
balanced ``{...}`` from left to right (never one nested in another), each as written and then
with trailing commas removed; control characters inside strings are accepted. An object nested in
a broken one is never taken for the answer: ``{"actions": [{"type": "wait"}`` is an error,
not a wait. Failures raise ``ModelOutputError`` (a ``ValueError``) with a message meant to be
shown to the model.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from typing import Any

from assistantx.core.errors import ModelOutputError

_FENCE = re.compile(r"```[ \t]*(?:json5?|JSON)?[ \t]*\n?(.*?)```", re.DOTALL)
_THINK = re.compile(r"<think>.*?</think>", re.DOTALL | re.IGNORECASE)
# A bound on the work done on a pathological answer (thousands of stray braces).
_MAX_CANDIDATES = 64


def extract_json_object(text: str) -> dict[str, Any]:
    """The first JSON object in ``text``; ``ModelOutputError`` naming the problem if none."""
    cleaned = _THINK.sub("", text).strip()
    if not cleaned:
        raise ModelOutputError("the answer was empty; expected one JSON object")
    first_error: json.JSONDecodeError | None = None
    saw_non_object: str | None = None
    for candidate in _candidates(cleaned):
        for variant in (candidate, remove_trailing_commas(candidate)):
            try:
                value = json.loads(variant, strict=False)
            except json.JSONDecodeError as exc:
                first_error = first_error or exc
                continue
            if isinstance(value, dict):
                return value
            saw_non_object = saw_non_object or type(value).__name__
            break
    if first_error is not None and "{" in cleaned:
        raise ModelOutputError(f"the answer is not valid JSON: {first_error}")
    if saw_non_object is not None:
        kind = {"list": "an array", "str": "a string"}.get(saw_non_object, saw_non_object)
        raise ModelOutputError(f"expected one JSON object, got {kind}")
    raise ModelOutputError("no JSON object found in the answer")


def _candidates(text: str) -> Iterator[str]:
    yield text
    for match in _FENCE.finditer(text):
        yield match.group(1).strip()
    # Top-level objects only: after a balanced candidate the search resumes past its end, and
    # an unclosed one swallows the rest, so nothing nested inside a candidate is tried alone.
    start = text.find("{")
    count = 0
    while start >= 0 and count < _MAX_CANDIDATES:
        end = _balanced_end(text, start)
        if end is None:
            return
        yield text[start : end + 1]
        count += 1
        start = text.find("{", end + 1)


def _string_step(c: str, escaped: bool) -> tuple[bool, bool]:
    """One character on inside a JSON string: (still inside it, the next one is escaped)."""
    if escaped:
        return True, False
    if c == "\\":
        return True, True
    return c != '"', False


def _balanced_end(text: str, start: int) -> int | None:
    """Index of the brace closing the one at ``start``, skipping braces inside strings."""
    depth = 0
    in_string = False
    escaped = False
    for i in range(start, len(text)):
        c = text[i]
        if in_string:
            in_string, escaped = _string_step(c, escaped)
        elif c == '"':
            in_string = True
        elif c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0:
                return i
    return None


def remove_trailing_commas(text: str) -> str:
    """Drop commas that directly precede ``}`` or ``]`` (whitespace between), outside strings."""
    out: list[str] = []
    in_string = False
    escaped = False
    pending_comma: int | None = None  # index in ``out`` of a comma that may be trailing
    for c in text:
        if in_string:
            out.append(c)
            in_string, escaped = _string_step(c, escaped)
            continue
        if c in "}]" and pending_comma is not None:
            del out[pending_comma]
            pending_comma = None
        elif c == ",":
            pending_comma = len(out)
        elif not c.isspace():
            pending_comma = None
        if c == '"':
            in_string = True
        out.append(c)
    return "".join(out)
