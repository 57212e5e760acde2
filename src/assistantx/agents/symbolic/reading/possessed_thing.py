"""The thing a possessive owns, past the words that describe it: "Kit's *signed* statement",
"Bob's *blue* stapler", "Lee's *old broken* charger".

English puts adjectives and participles between the owner and the thing; the owner still
owns the thing. Read only as the next mention, a describing word hid the thing, so a
possessive naming nobody in the office was not asked about and the requester's own thing
(or anyone's) was used in its place: a wrong physical action."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language

# "Lee's old broken charger": the most describing words read between an owner and the thing
_MOST_DESCRIBING = 3


def possessed(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> Mention | None:
    """The mention the possessive at ``mentions[n]`` owns: the next one, past up to three
    describing words written in lower case right after each other ("signed", "blue"); None
    when nothing follows. A pause or a new sentence ends the phrase."""
    k = n + 1
    while k < len(mentions) and k - n <= _MOST_DESCRIBING:
        m = mentions[k]
        if m.kind != "word" or m.end - m.start != 1 or not _describes(tokens[m.start]):
            break
        if m.start != mentions[k - 1].end or tokens[m.start].after_pause:
            break
        k += 1
    return mentions[k] if k < len(mentions) else None


def _describes(token: Token) -> bool:
    """A lower-case adjective or participle ("blue", "signed", "broken", "working")."""
    if not token.text[:1].islower() or token.opens:
        return False
    word = token.word
    return (
        "ADJ" in language.lemmas(word)
        or language.is_past_participle(word)
        or language.is_present_participle(word)
    )
