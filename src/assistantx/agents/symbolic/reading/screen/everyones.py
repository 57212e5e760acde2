"""Everyone's: "wipe all the drives in the vault", "bring me every stapler", "shred each
folder on the shelf", "collect everyone's mugs": a request over every one of a kind that
colleagues own is declined in words. Each owner's yes is asked in their own chat before any of
their things moves or is worked on, one thing at a time, so "all of them" is no request the
robot can carry out; the requester may name whose thing they mean and ask again. Never read
as the requester's own one: that turned "wipe all the drives" into wiping theirs.

Only a request (request wording, an imperative, or a plain verb first) whose quantifier
stands before an item the office's people own: "all my drives" and "all of mine" are the
speaker's own and read as before, as are things nobody owns (supplies kept at a place, made
products: "bring all the gloves from the stores"), files ("print all the files") and a quantifier
that takes in no item ("thanks all", "that's all, bring me a pen")."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.destructive import commanded
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language

_EVERY = english.words("universal_quantifiers")
# what may stand between the quantifier and the thing: "all *of the* old drives"
_BETWEEN = frozenset({"the", "of", "these", "those", "them"})
_OWN = frozenset({"my", "our", "mine", "ours"})
_EVERYONE = frozenset({"everyone", "everybody"})  # "everyone's mugs", the possessive apart
_DESCRIBING = 2  # "every spare hard drive": describing words before the item's name


def everyones(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not (piece.acts.request or piece.acts.imperative or commanded(terms, piece)):
        return None
    for m in piece.lexed.mentions:
        if m.kind != "item" or len(m.ids) != 1 or not _owned_by_colleagues(terms, m, requester):
            continue
        if _quantified(piece, m):
            things = terms.office.item_type(m.ids[0]).name
            return Finding(
                "unsupported",
                piece,
                "a request over everyone's things of a kind",
                message=(
                    f"Sorry, I can't do that to every {things}: each belongs to someone, "
                    "and I move or work on a colleague's thing only with that person's own "
                    f"yes, one at a time. Tell me whose {things} you mean and I'll ask them. "
                    "I did nothing."
                ),
            )
    return None


def _owned_by_colleagues(terms: Terms, m: Mention, requester: str) -> bool:
    office = terms.office
    if office.item_type(m.ids[0]).kind in ("product", "electronic"):
        return False  # made here, or a file: "print all the files" reads as before
    return any(p != requester for p in office.owners_of(m.ids[0]))


def _quantified(piece: Piece, m: Mention) -> bool:
    """Whether an "all"/"every"/"each"/"everyone's" stands before the item ``m``, with only
    "the"/"of" and up to two describing words between, and no "my"/"our" of the speaker's."""
    tokens = piece.lexed.tokens
    k = m.start - 1
    described = 0
    while k >= 0:
        word = tokens[k].word
        if word in _OWN:
            return False  # "all my drives": the speaker's own
        if word in _EVERY or (word in _EVERYONE and tokens[k].possessive):
            return True
        if word in _BETWEEN:
            k -= 1
            continue
        if described < _DESCRIBING and "ADJ" in language.lemmas(word) and not tokens[k].possessive:
            described += 1
            k -= 1
            continue
        return False
    return False
