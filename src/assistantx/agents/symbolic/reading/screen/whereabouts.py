"""Whereabouts: "fyi Dev's torch is back in the props cupboard", "gaffer tape's in the
cupboard again", "just so you know, you'll find the stapler by the copier": a statement of
where an item is. It is answered in words and never acted on: no fetch of the item it names
(a request beside it may still point back to it: "... it's in the cupboard, bring it to me").

Read by its shape, whatever the office: the item is the subject (after an opener, an article
or a possessive), then a verb of being or of having gone somewhere ("is", "'s", "are back",
"went back", "has been put"), then a place word ("in", "on", "back", "at the ..."); or "you'll
find <item> <place word>". A piece with a task word of its own is read on as a request."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.obligation import obliged_verb
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.statement import destination_stated, stated_items
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english
from assistantx.core.wording import is_are

_BEFORE_SUBJECT = english.words("determiners") | frozenset({"your", "the"})
# The verbs between the item and where it is: being there, or having been put or gone there.
_BEING = english.words("whereabouts_verbs")
_WHERE = english.words("whereabouts_places")
_FIND = (("youll", "find"), ("you", "will", "find"), ("you", "can", "find"), ("youd", "find"))


def whereabouts(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.asks or destination_stated(terms, msg, piece):
        return None  # "the parcel has to go off to Galway, courier it": where it is sent
    tokens = piece.lexed.tokens
    words = [t.word for t in tokens]
    said = content(_spelled_out(words))
    start = len(words) - len(said)
    found = next((p for p in _FIND if tuple(said[: len(p)]) == p), ())
    start += len(found)
    mentions = [_as_noun(terms, words, m) for m in piece.lexed.mentions if m.end > start]
    if any(m.kind == "cue" for m in mentions):
        return None  # a task word of its own: read on as a request
    subject = _subject(mentions, words)
    if subject is None:
        return None
    if obliged_verb(words, subject.end) is not None:
        return None  # "Pat's book has to go to Sam": an obligation, never where it is
    after = words[subject.end :]
    verb = tokens[subject.end - 1].possessive  # "tape's in": the 's is the "is"
    n = 0
    while n < len(after) and after[n] in _BEING:
        n, verb = n + 1, True
    if n >= len(after) or after[n] not in _WHERE or not (verb or found):
        return None
    kind = terms.office.item_type(subject.ids[0])
    thing, be = kind.name, is_are(kind.name, mass=kind.mass)
    stated = tuple(stated_items(terms, piece, requester))
    return Finding(
        "statement",
        piece,
        f"a statement of where the {thing} {be}",
        message=f"Thanks for telling me where the {thing} {be}.",
        context=stated,
    )


def _as_noun(terms: Terms, words: list[str], m: Mention) -> Mention:
    """ "your copy is at the copier": a task word that also names an item, after a
    determiner or a possessive, is the item."""
    word = words[m.start]
    if m.kind != "cue" or word not in terms.lex.items or m.start == 0:
        return m
    if words[m.start - 1] not in _BEFORE_SUBJECT and words[m.start - 1] not in ("my", "mine"):
        return m
    return Mention("item", m.start, m.end, (terms.lex.items[word],), m.possessive, m.text)


def _subject(mentions: list[Mention], words: list[str]) -> Mention | None:
    """The item the piece is about: its first item mention, with only an article or a
    possessive (mine, a colleague's) before it."""
    for m in mentions:
        if m.kind == "item":
            return m if len(m.ids) == 1 else None
        possessive = m.possessive and m.kind in ("person", "self", "pronoun")
        if not possessive and not (m.kind == "word" and words[m.start] in _BEFORE_SUBJECT):
            return None
    return None


def _spelled_out(words: list[str]) -> list[str]:
    """ "just so u know": the chat spelling of "you", so the stance phrase is found."""
    return ["you" if w == "u" else w for w in words]
