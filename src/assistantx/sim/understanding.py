"""How a simulated person reads a message: which item types and which requests it mentions.

This is the simulator's stand-in for a human reader, so keyword spotting is enough: it
decides what a rule-based person understood, not what the assistant meant.
"""

from __future__ import annotations

import re

from assistantx.core import english
from assistantx.core.office import Office
from assistantx.core.task_schema import FILE_KIND, PERSON_KINDS
from assistantx.memory.names import normalize

# The task schema's person-to-person kinds → the English words that signal them (the package's
# English data file); the office's own operations are signalled by their verbs and their
# product's names (``request_words``).
PERSON_REQUEST_WORDS: dict[str, tuple[str, ...]] = {
    kind: english.kind_words(kind) for kind in PERSON_KINDS
}
SEND_FILE_WORDS = english.kind_words(FILE_KIND)


def request_words(office: Office) -> dict[str, tuple[str, ...]]:
    """Request kind (or operation id) → the words that signal it, in the office's order."""
    words = dict(PERSON_REQUEST_WORDS)
    for op in office.operations:
        if not office.runnable(op.id):
            continue
        found = [normalize(v) for v in op.verbs]
        if op.product is not None:
            product = office.item_type(op.product)
            found += [normalize(n) for n in (product.name, *product.synonyms)]
        words[op.id] = tuple(w for w in dict.fromkeys(found) if w)
    words[FILE_KIND] = SEND_FILE_WORDS
    return words


def _words(text: str) -> str:
    return f" {normalize(text)} "


def mentioned_item_types(office: Office, text: str) -> list[str]:
    """Item types named in ``text`` (longest names first, so 'data cable' beats 'cable')."""
    haystack = _words(text)
    found: list[str] = []
    names = sorted(
        ((normalize(n), t.id) for t in office.item_types for n in (t.id, t.name, *t.synonyms)),
        key=lambda pair: -len(pair[0]),
    )
    for name, type_id in names:
        if not name:
            continue
        for variant in (name, name + "s", name + "es"):
            if f" {variant} " in haystack and type_id not in found:
                found.append(type_id)
                haystack = haystack.replace(f" {variant} ", " ")
    return found


def mentioned_requests(office: Office, text: str) -> list[str]:
    """Request kinds the text mentions. The office's own words are read first and used up, so
    an English word inside one ("stamp" in "stamped envelope") does not count again."""
    haystack = _words(text)
    found: set[str] = set()
    words = request_words(office)
    for kind in (k for k in words if k not in PERSON_REQUEST_WORDS):
        for w in words[kind]:
            if re.search(rf" {re.escape(w)}\w* ", haystack):
                found.add(kind)
                haystack = re.sub(rf" {re.escape(w)}\w* ", " ", haystack)
    for kind, kind_words in PERSON_REQUEST_WORDS.items():
        if any(re.search(rf" {w}\w* ", haystack) for w in kind_words):
            found.add(kind)
    return [k for k in words if k in found]


def is_question(text: str) -> bool:
    t = normalize(text)
    return "?" in text or t.startswith(("can ", "could ", "would ", "do ", "does ", "are ", "is "))
