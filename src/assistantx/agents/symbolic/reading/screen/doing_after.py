"""Doing after a request: "could you bring me an ice bucket? Running minipreps in 10",
"print my rota, binding the report at 3": a piece that opens with a present participle, its
subject left out, said after a request, is what the speaker is doing, the reason for the
request, even where the participle is the verb of one of the office's services ("run",
"print"). Said alone ("printing my slides please") or asking ("printing my slides?") it is
read on as before; a participle of fetching ("bringing", "grabbing") is an errand's own."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language

# Verbs of an errand itself: "bringing the kit over?" is no doing of the speaker's.
_ERRAND_VERBS = english.words("handing_verbs") | english.words("dative_verbs")
# Words that ask, whatever opens the piece: "printing my slides too please" is a request.
_ASKING = frozenset({"please", "pls", "plz", "too", "also", "as", "well"})


def doing_after(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.asks or piece.acts.question is not None:
        return None
    if not any(p.acts.request and p.end <= piece.start for p in msg.pieces if p is not piece):
        return None  # alone, or before the request: it may be the request itself
    words = content(piece.words)
    if not words or not _service_participle(terms, words[0]):
        return None
    if set(words) & _ASKING:
        return None
    return Finding("statement", piece, "what the speaker is doing, context only")


def _service_participle(terms: Terms, word: str) -> bool:
    """A present participle of one of the office's services ("running", "printing"), or of
    any verb that asks for no task ("running minipreps in 10" where nothing here runs: the
    thing it names is the speaker's, not one to fetch); never one of fetching or handing
    ("bringing", "grabbing"), an errand's own."""
    if not word.endswith("ing") or word in terms.lex.items:
        return False
    lemmas = language.verb_lemmas(word)
    if not lemmas or word in lemmas:
        return False
    if lemmas & terms.service_verbs:
        return True
    return not lemmas & (terms.lex.cue_words | _ERRAND_VERBS)
