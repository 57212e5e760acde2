"""Where a service that sends an item outside the office sends it ("fax my form to the county
tax office"): the words after "to" that follow the service's verb, as the requester wrote them.

The destination is outside the office, so it is never a name the lexicon knows; it is kept in
the requester's own words (a number, an organisation) for the outcome the requester reads.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

# What ends a destination: a sentence or clause end, or a courtesy word after it.
_END = re.compile(r"[.!?;,\n]|\s+(?:please|pls|thanks|thank you|thx|asap|today|now)\b", re.I)
_LONGEST = 80  # a destination longer than this is not one phrase: ask instead


def destination(text: str, verbs: Iterable[str]) -> str | None:
    """The phrase after the first "to" that follows one of ``verbs`` (inflected forms, lower
    case) in ``text``; None when the text names no destination."""
    forms = sorted({v for v in verbs if v}, key=len, reverse=True)
    if not forms:
        return None
    verb = re.search(r"\b(?:" + "|".join(map(re.escape, forms)) + r")\b", text, re.I)
    if verb is None:
        return None
    clause = re.split(r"[.!?;,\n]", text[verb.end() :], maxsplit=1)[0]
    to = re.search(r"\bto\s+", clause, re.I)  # in the verb's own clause ("…, it has to go")
    if to is None:
        return None
    rest = text[verb.end() + to.end() :]
    end = _END.search(rest)
    phrase = (rest[: end.start()] if end else rest).strip().strip("\"'")
    if not phrase or len(phrase) > _LONGEST:
        return None
    return phrase
