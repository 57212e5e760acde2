"""Negation: "don't bring me ...", "no need to print ...", "don't bother fetching ...": the
piece is dropped; with nothing else asked, the message is answered "OK, I won't"."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms


def negated(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    words = piece.words
    for at in range(len(words)):
        for neg in terms.en.negators:
            if not starts_with(words, at, neg):
                continue
            if at and words[at - 1] not in terms.en.lead_in:
                continue  # "I can't find my stapler": not the request verb
            if terms.request_verb(words, at + len(neg) - 1):
                return Finding("negated", piece, f"negated: {' '.join(neg)}")  # "no longer need"
            k = at + len(neg)
            while k < len(words):  # "don't actually need", "do not ever print"
                if terms.request_verb(words, k) or terms.errand_gerund(words[k]):
                    return Finding("negated", piece, f"negated: not to {words[k]}")
                if words[k] not in terms.en.negation_fillers:
                    break
                k += 1
    return None
