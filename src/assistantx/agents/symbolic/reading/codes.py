"""Short capitalised codes that are nobody's name ("the bag for LIS", "the trolley from T2").

An airport, a room, a flight or a stand is often written as a short code in capitals ("LIS",
"BA117", "B4"). Written after a plain noun and a preposition ("bag for LIS", "crate from
AMS") it says which thing is meant, not who gets it: the readings stage asks "who is LIS?"
of no such code. A code of the office's own (a colleague's initials declared as an alias,
"DK") is a name of the lexicon and never reaches this test; a code right after a request's
item ("a rush tag for LIS") or after "ask" or a title stays a name to ask about, since there
it would say who the item is for.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import COMMON, PRONOUNS, Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# Prepositions after which a code says where a thing goes, comes from or what it is for.
_CODE_PREPOSITIONS = frozenset({"for", "from", "to", "at", "on", "via"})
_PLACE_WORDS = english.words("place_words")  # "to the desk for JT": JT may sit there
_LONGEST_CODE = 4  # "LIS", "GATE" is a word; letters and digits make a code at any length


def looks_like_code(written: str) -> bool:
    """Whether a word as written is a code: all capitals, two to four letters ("LIS",
    "ORD"), or letters and digits together ("BA117", "B4")."""
    word = written.replace("’", "'").removesuffix("'s").removesuffix("'")
    if len(word) < 2 or not word.isalnum() or word.upper() != word:
        return False
    if any(c.isdigit() for c in word):
        return any(c.isalpha() for c in word)
    return len(word) <= _LONGEST_CODE


def code_of_a_thing(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """Whether mention ``n`` (a word nobody in the office is called) is a code that names
    which plain thing the noun before its preposition is: "bag for LIS" (a noun naming none
    of the office's items, then "for", then the code); never a possessive ("LIS's bag")."""
    m = mentions[n]
    if m.possessive or not looks_like_code(m.text) or m.start < 2:
        return False
    if tokens[m.start - 1].word not in _CODE_PREPOSITIONS:
        return False
    noun_at = m.start - 2
    noun = next((k for k in mentions if k.start <= noun_at < k.end), None)
    if noun is None or noun.kind != "word" or tokens[noun_at].possessive:
        return False
    word = tokens[noun_at].word
    if word in COMMON or word in PRONOUNS or word in _PLACE_WORDS:
        return False
    return language.is_noun(word)
