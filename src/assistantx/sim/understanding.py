"""How a simulated person reads a message: which item types and which requests it mentions.

This is the simulator's stand-in for a human reader, so keyword spotting is enough: it
decides what a rule-based person understood, not what the assistant meant.
"""

from __future__ import annotations

import re

from assistantx.memory.names import normalize
from assistantx.office import Office

# request kind → words that signal it
REQUEST_WORDS: dict[str, tuple[str, ...]] = {
    "sign": ("sign", "signature", "signed"),
    "seal": ("seal", "stamp", "chop"),
    "print": ("print", "printout", "printed"),
    "copy": ("copy", "photocopy", "copies", "photocopies"),
    "coffee": ("coffee", "latte", "espresso", "americano", "cappuccino"),
    "water": ("water",),
    "heat": ("heat", "warm", "microwave"),
    "vend": ("vending", "snack", "buy", "chips", "soda"),
    "send_file": ("send", "share", "forward", "email"),
}

# facility operation a request needs
REQUEST_OPERATION = {
    "print": "print",
    "copy": "copy",
    "coffee": "coffee",
    "water": "water",
    "heat": "heat",
    "vend": "vend",
}


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


def mentioned_requests(text: str) -> list[str]:
    haystack = _words(text)
    return [
        kind
        for kind, words in REQUEST_WORDS.items()
        if any(re.search(rf" {w}\w* ", haystack) for w in words)
    ]


def is_question(text: str) -> bool:
    t = normalize(text)
    return "?" in text or t.startswith(("can ", "could ", "would ", "do ", "does ", "are ", "is "))
