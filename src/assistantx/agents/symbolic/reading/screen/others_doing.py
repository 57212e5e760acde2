"""A colleague's own doing: "Priya needs to measure a carton. take her my tape measure pls",
"Zhang needs to cut some paper, bring him my scissors". A colleague who needs (has, wants) to
do something that is no errand or service of the office ("measure", "staple", "cut"), said
beside a request that names a thing of its own, says what the colleague will work on with
that thing: the object of their doing ("a carton", "some paper") is nothing to fetch, so the
piece is context, and the colleague stays the one the request's "her"/"him" means. A doing
that is an errand or a service here ("needs to print a report") or a colleague's own work on
a thing ("needs to sign my form", the thing handed for it) is read as before, and so is one
beside a request that names no thing ("... can you take it to her": "it" is that object)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.obligation import PERSON_WORK
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.own_doing import after_plan, infinitive
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content

# "needs to", "has to", "wants to", "has got to": a colleague's plan or obligation
_PLAN = frozenset({"needs", "need", "has", "have", "wants", "want", "got", "must"})
_BETWEEN = frozenset({"still", "just", "really", "also", "first", "got"})


def others_doing(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.imperative or piece.acts.question is not None or piece.asks:
        return None
    subject = colleague_first(piece, requester)
    if subject is None:
        return None
    if not any(
        p.acts.request and terms.named(p.lexed, "item") for p in msg.pieces if p.start > piece.start
    ):
        return None  # alone, or before "take it to her": its object may be the thing asked
    tokens = piece.lexed.tokens
    words = content([t.word for t in tokens[subject:]])
    rest = after_plan(words, _PLAN, _BETWEEN)
    if not rest:
        return None
    verb = rest[0]
    if verb in terms.service_verbs or verb in terms.lex.cue_words or verb in PERSON_WORK:
        return None  # "needs to print a report", "needs to sign my form": asked
    if terms.request_verb(rest, 0) or not infinitive(words, rest):
        return None  # "needs to get a stapler": an errand, read on
    return Finding("statement", piece, "a colleague's own doing, context only")


def colleague_first(piece: Piece, requester: str) -> int | None:
    """Where the words after the piece's subject start, when the piece opens with one
    colleague's name (not a possessive, not the speaker): "Priya needs ..." → 1."""
    mentions = piece.lexed.mentions
    if not mentions:
        return None
    first = mentions[0]
    if first.start != 0 or first.kind != "person" or first.possessive:
        return None
    if len(first.ids) != 1 or first.ids[0] == requester:
        return None
    return first.end
