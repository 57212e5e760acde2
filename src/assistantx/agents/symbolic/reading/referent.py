"""The item a request points back to in another sentence: "Olive has a craft knife, could
you bring *it* to me", "is there any foam board left? If so bring me *a sheet*".

A clause that asks to bring something and names no item of the office, but a pronoun ("it",
"that", "one") or a unit of a thing ("a sheet", "a piece", "a couple"), means the one item the
whole message names elsewhere (the frames' ``named``); whose it is, is whose the other
sentence said it was ("Olive has ...": hers, still asked for). Two items named, or none, leave
the clause as it was: asked, never guessed. The unit words are English, not the office's.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

NamedItem = tuple[str, str | None]  # an item type and whose it was said to be (None: unsaid)

# the portions that point back ("a sheet"), not every unit: "anyone got a mug? bring me a
# set" leaves open a set of what
_UNITS = english.words("portion_words")
_POINTERS = frozenset({"it", "that", "this", "one", "some", "them"})
_ARTICLES = frozenset({"a", "an", "one", "another", "some"})
# words after a unit that end its phrase though a dictionary also lists them as nouns
_FUNCTION = frozenset({"please", "now", "too", "then", "if", "thanks", "here", "today"})
# "would *it be* possible to ...", "*it's* urgent": "it" as the subject of a copula points at
# nothing moved (one-word copulas of english.yaml, and the bare "be" after a modal)
_COPULAS = frozenset(c for c in english.entries("copulas") if " " not in c) | {"be"}
# the cues of a clause that moves a thing to someone
_MOVING = frozenset({"give"})


def referent(
    clause: Clause, tokens: Sequence[Token], named: Sequence[NamedItem]
) -> tuple[Mention, str | None] | None:
    """The item ``clause`` points back to, as a mention at the pointing word, and whose it
    was said to be; None when the clause names an item, moves nothing, points at nothing, or
    the message names no single item elsewhere."""
    if clause.objects() or not clause.cues & _MOVING:
        return None
    kinds = {item for item, _ in named}
    if len(kinds) != 1:
        return None
    at = next((m for m in clause.mentions if _points(m, tokens)), None)
    if at is None:
        return None
    item = next(iter(kinds))
    owners = {owner for i, owner in named if i == item and owner is not None}
    owner = next(iter(owners)) if len(owners) == 1 else None
    return Mention("item", at.start, at.end, (item,), False, at.text), owner


def _points(m: Mention, tokens: Sequence[Token]) -> bool:
    """ "it", "that", "one": a pronoun; "a sheet", "a couple": a unit after an article."""
    word = tokens[m.start].word
    if m.kind == "pronoun" and not m.possessive:
        subject = m.end < len(tokens) and tokens[m.end].word in _COPULAS
        return word in _POINTERS and not (word == "it" and subject)
    if m.kind != "word" or _modifies(tokens, m.end):
        return False  # "one battery", "a spare battery": a thing of its own, not named
    if word in _POINTERS - {"this", "that"}:
        return True  # "bring me one", "get me some"
    before = tokens[m.start - 1].word if m.start else ""
    return word in _UNITS and before in _ARTICLES


def _modifies(tokens: Sequence[Token], at: int) -> bool:
    """Whether the word before ``at`` modifies a noun that follows it ("one battery"), which
    is then what the clause is about ("a sheet of ..." and "one for me" point back)."""
    if at >= len(tokens):
        return False
    nxt = tokens[at].word
    return nxt != "of" and language.is_noun(nxt) and nxt not in _FUNCTION
