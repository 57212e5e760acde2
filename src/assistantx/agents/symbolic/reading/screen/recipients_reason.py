"""Why the one a request gives to needs it: "copy my document and give the copy to Wang, he
needs it for his file", "print my report and bring it to Wang, he needs it for his meeting".
After a request that names a colleague, "he/she/they need(s) it for <anything>" points back to
the thing asked for ("it") and to that colleague ("he"): it says why, and is context only. What
comes after "for" ("his file") is the purpose, never a second thing or the thing "the copy"
is of. A need of a thing of its own ("he needs his file"), a need said with no request before
it, a need by a time ("he needs it by 3") or with no colleague named in the request ("bring
the stapler, she needs it": whom "she" means is read as before) are read as before."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

_NEED = english.words("need_verbs")
# The third person a reason is said of: the colleague the request named.
_THIRD = frozenset({"he", "she", "they"})
# Words that may stand between the subject and its verb without changing the need.
_ADVERBS = frozenset({"really", "just", "still", "only", "also", "urgently"})
# What points back to the thing just asked for.
_BACK = frozenset({"it", "them", "that", "this", "those", "these"})
# A word that says when ("at 3", "by noon", "tomorrow"): a time is kept for the planner.
_TIME = re.compile(
    r"\d|^(?:am|pm|noon|midday|today|tonight|tomorrow|morning|afternoon|evening|asap|soon|now)$"
)
_FROM = "from"


def recipients_reason(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.imperative or acts.question is not None:
        return None
    words = content(piece.words)
    at = next((n for n, w in enumerate(words) if w in _NEED), None)
    if at is None or not words[:at] or words[0] not in _THIRD:
        return None
    if not set(words[1:at]) <= _ADVERBS or words[at + 1 : at + 2] == []:
        return None
    if words[at + 1] not in _BACK:
        return None  # "he needs his file": a thing of its own
    rest = words[at + 2 :]
    if rest and (rest[0] != "for" or any(_TIME.search(w) for w in rest)):
        return None  # "he needs it by 3", "he needs it for 2pm": when, read as before
    if terms.named(piece.lexed, "person"):
        return None  # "Rena needs it": a name of its own, read as before
    earlier = [p for p in msg.pieces if p.end <= piece.start]
    if not any((p.acts.request or p.acts.imperative) and _party(p) for p in earlier):
        return None
    return Finding("statement", piece, "why the colleague the request names needs it: context")


def _party(piece: Piece) -> bool:
    """Whether the request names a colleague who is no owner or source of the thing ("to
    Wang", "for Wang", "give Wang the copy"; not "Wang's stapler", "from Wang")."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    return any(_not_source(tokens, m) for m in mentions if m.kind == "person")


def party_ids(piece: Piece) -> set[str]:
    """The colleagues a request names who are no owner or source of the thing (``_party``),
    each named as one person."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    return {
        m.ids[0]
        for m in mentions
        if m.kind == "person" and len(m.ids) == 1 and _not_source(tokens, m)
    }


def _not_source(tokens: tuple[Token, ...], m: Mention) -> bool:
    if m.possessive:
        return False
    return not (m.start and tokens[m.start - 1].word == _FROM)
