"""Negation: "don't bring me ...", "no need to print ...", "don't bother fetching ...": the
piece is dropped; with nothing else asked, the message is answered "OK, I won't"."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.named_words import named_at
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.still_needed import still_needed
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language

# "Otto's lending me his", "we're off site": a statement with its verb contracted.
_CONTRACTION = re.compile(r"\w['’](?:s|re|m|ve|ll)\b")


def negated(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    found = negation(terms, piece)
    if found is not None:
        msg.negating = True
        return found
    if msg.negating and still_needed(piece):
        # "don't shred my document, I still need it for the meeting": why it is not wanted
        return Finding("negated", piece, "the speaker still needs it: why the errand is not wanted")
    if msg.negating and _told_reason(terms, msg, piece):
        # "don't bother bringing the level, Otto's lending me his": why the errand is not
        # wanted, told as what is happening, not an errand of its own
        return Finding("negated", piece, "the reason the errand is not wanted")
    return None


def _told_reason(terms: Terms, msg: Message, piece: Piece) -> bool:
    """A piece after a negated errand that tells something (a finite verb, a contracted
    "'s") and asks nothing, with no request after it in the message."""
    told = any(language.is_finite_verb(w) for w in piece.words) or bool(
        _CONTRACTION.search(piece.text)
    )
    later = [p for p in msg.pieces if p.start >= piece.start]
    return told and not piece.asks and not any(p.acts.request for p in later)


def negation(terms: Terms, piece: Piece) -> Finding | None:
    """The piece's own negated errand ("don't bring me ...", "no need to print ...")."""
    words = piece.words
    for at in range(len(words)):
        for neg in terms.en.negators:
            if not starts_with(words, at, neg):
                continue
            if at and words[at - 1] not in terms.en.lead_in:
                continue  # "I can't find my stapler": not the request verb
            if len(neg) == 1 and named_at(piece, piece, at):
                continue  # "Skip needs a ruler": a colleague called Skip, no negator
            if terms.request_verb(words, at + len(neg) - 1):
                return Finding("negated", piece, f"negated: {' '.join(neg)}")  # "no longer need"
            k = at + len(neg)
            while k < len(words):  # "don't actually need", "do not ever print"
                if terms.request_verb(words, k) or terms.errand_gerund(words[k]):
                    return Finding("negated", piece, f"negated: not to {words[k]}")
                # "don't shred my document": a verb that destroys, called off, is no errand
                # to decline, whether the office has the machine or not
                if any(starts_with(words, k, d) for d in terms.en.destructive):
                    return Finding("negated", piece, f"negated: not to {words[k]}")
                if words[k] not in terms.en.negation_fillers:
                    break
                k += 1
    return None
