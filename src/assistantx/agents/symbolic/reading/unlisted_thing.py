"""A thing asked for from a facility that the office does not list: "bring me 50 ml of
chloroform from the chem store", where the store only makes ethanol. The word that heads the
object, right before "from/at/in/out of" the facility, names the thing; when it is no item of
the office (no mention of one) and no everyday filler ("one", "some"), it is that unlisted
thing, declined by name, never swapped for what the facility makes or keeps."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core import english

_COMMON = english.words("common")
_FROM_WORDS = frozenset({"from", "at", "in", "of", "out"})


def unlisted_thing(mentions: Sequence[Mention]) -> tuple[str, str] | None:
    """The unlisted thing asked for from a facility and that facility's id, or None."""
    for n, m in enumerate(mentions):
        if m.kind != "facility" or n < 2:
            continue
        k = n - 1
        while k >= 0 and mentions[k].kind == "word" and mentions[k].ids[0] in _FROM_WORDS:
            k -= 1  # "out of the store", "from the store"
        if k == n - 1 or k < 0:
            continue
        head = mentions[k]
        if head.kind != "word" or head.possessive:
            continue
        word = head.ids[0]
        if word in _COMMON or not word.isalpha() or len(word) < 3:
            continue
        return head.text.lower(), m.ids[0]
    return None
