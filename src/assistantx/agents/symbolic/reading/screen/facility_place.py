"""A facility named with where it stands ("the kitchen coffee machine", "copy room printer",
"the upstairs fridge") is the facility: English puts a place or another noun before a noun
as its modifier, so a report about it ("kitchen coffee machine is leaking again", "copy
room printer is broken", "print room printer keeps jamming") is the same report as about
"the coffee machine", answered in words. Before, the place word made the piece unread
("Sorry, I'm not sure what you need") or, where it was a service's verb ("copy room"), a
service declined. A failure said with "has" ("the kettle has died") is a fault too."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_FAILED = tuple(
    sorted((tuple(p.split()) for p in english.entries("facility_failed")), key=lambda p: -len(p))
)
_HAS = (("has", "just"), ("has", "now"), ("has", "finally"), ("has",), ("s",), ("have",))


def _modifier(word: str) -> bool:
    """A word that can stand before a noun as its modifier and is no verb ("kitchen",
    "upstairs", "old"): never "fix" or "check", which would open a command."""
    read = set(language.lemmas(word))
    return bool(read & {"NOUN", "ADJ"}) and "VERB" not in read


def facility_after_place(tokens: Sequence[Token], mentions: Sequence[Mention], k: int) -> int:
    """Where the facility mention is when mentions[k:] open with a place of the office or
    modifier words and then a facility ("kitchen" "coffee machine"); ``k`` otherwise."""
    n = k
    while n < len(mentions) and n - k < 3:
        m = mentions[n]
        if m.kind == "place" or (m.kind == "word" and _modifier(tokens[m.start].word)):
            n += 1
            continue
        break
    if n > k and n < len(mentions) and mentions[n].kind == "facility":
        return n
    return k


def failure_said(rest: Sequence[str]) -> list[str]:
    """ "has died again" → ["died"]: the failure said after "has", or [] for none."""
    for has in _HAS:
        if tuple(rest[: len(has)]) != has:
            continue
        after = list(rest[len(has) :])
        for failed in _FAILED:
            if tuple(after[: len(failed)]) == failed:
                return list(failed)
    return []
