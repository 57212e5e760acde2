"""An elided possessive refers back: "my stapler's broken, can I have Wang's? and grab me a
coffee too" asks for Wang's stapler and a coffee, not Wang's coffee. English leaves the noun
out of "X's" (and "mine") only where the listener already has it, so the thing meant is the
nearest one named *before* the possessive; a noun named after it fills it only where nothing
was named before ("can I have Wang's? the stapler, I mean"). A thing's word said bare after
a preposition of time or going ("took the stapler *to lunch*", "*at lunch*") names an
occasion, not a thing anyone holds, so it is never what the possessive means
(``things_named``).

The rule reads the whole message (its tokens and the lexicon's mentions), because the piece
the possessive stands in may have lost the clause that named the thing ("my stapler's
broken" is screened as a statement of its own)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexed, Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language


def elided_item(lexed: Lexed, word: str) -> str | None:
    """The item type id the elided possessive ``word`` ("Wang's", "mine") of the message
    ``lexed`` stands for: the last item named before it, else the first named after it; None
    where the message names no item, or where ``word`` is not found as such a possessive."""
    items = things_named(lexed.tokens, lexed.mentions)
    if not items:
        return None
    at = _position(lexed, word)
    if at is None:
        return None
    before = [m for m in items if m.end <= at]
    if before:
        return before[-1].ids[0]
    after = [m for m in items if m.start > at]
    return after[0].ids[0] if after else None


# "to lunch", "at lunch", "after lunch": a bare noun after these names when or where, an
# occasion; with a determiner ("to the stapler", "after my lunch") it is a thing again
_OCCASION_PREPOSITIONS = frozenset(
    {"to", "at", "after", "before", "during", "over", "till", "until", "from"}
)


def things_named(tokens: Sequence[Token], mentions: Sequence[Mention]) -> list[Mention]:
    """The item mentions of ``mentions`` that name a thing, in order: not those said bare
    right after a preposition of time or going ("took the stapler to lunch": lunch is when,
    not a thing), which an elided possessive never means."""
    items = [m for m in mentions if m.kind == "item"]
    return [
        m
        for m in items
        if not (
            m.start > 0 and tokens[m.start - 1].word in _OCCASION_PREPOSITIONS and not m.possessive
        )
        and not _purpose_of(tokens, mentions, items, m)
    ]


# how many words may stand between "for" and the thing a purpose names ("for *her moss*
# packets")
_PURPOSE_WORDS = 3
# what may stand there: plain words and whose it is ("for *her* moss packets", "for *my* labels")
_DESCRIBING = frozenset({"word", "pronoun", "self"})


def _purpose_of(
    tokens: Sequence[Token], mentions: Sequence[Mention], items: Sequence[Mention], m: Mention
) -> bool:
    """Whether item ``m`` is what another thing named before it is for ("a bone folder *for
    her moss packets*, can you take mine"): the thing worked on, never the one lent, so an
    elided possessive never means it."""
    at = m.start - 1
    while at >= 0 and m.start - at <= _PURPOSE_WORDS and tokens[at].word != "for":
        if any(x.start <= at < x.end and x.kind not in _DESCRIBING for x in mentions):
            return False  # a person, a place or another thing between: no plain purpose
        at -= 1
    if at < 1 or tokens[at].word != "for":
        return False
    return any(x.end == at for x in items)


def _position(lexed: Lexed, word: str) -> int | None:
    """The token index of ``word`` said with no item after it: the first "mine"/"yours", or
    the first possessive token of the name ("Wang" of "Wang's") whose next token opens no
    item (an "X's stapler" somewhere else in the message is a possessive with its noun)."""
    key = language.fold(word).replace("’", "'")
    possessive = key.endswith("'s")
    key = key.removesuffix("'s")
    tokens = lexed.tokens
    for n, t in enumerate(tokens):
        if t.word != key and t.typed != key:
            continue
        if possessive != t.possessive:
            continue
        if not _item_at(lexed.mentions, n + 1):
            return n
    return None


def _item_at(mentions: Sequence[Mention], n: int) -> bool:
    return any(m.kind == "item" and m.start == n for m in mentions)
