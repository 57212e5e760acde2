"""An acknowledgement: "crystal clear, thanks!", "sounds good", "fair enough", "will do",
"got it", "grand, cheers": a set phrase said back to what the assistant or a colleague said.
It asks for nothing, so it is answered in words and nothing moves.

It is read from the words as typed (before the lexicon's typo correction, which would read
"grand" as a colleague called Grant), and only where the whole piece is the phrase, with
its lead-in ("ok", "that's") and its courtesy ("thanks", "mate") around it: a colleague
whose name is a word of the phrase ("Crystal", "Sunny") is not named by it, while
"Crystal's stapler please" names her thing and is read as a request."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.english import entries as english_entries
from assistantx.core.english import words as english_words

_PHRASES = frozenset(tuple(p.split()) for p in english_entries("acknowledgements"))
_LEAD_INS = english_words("acknowledgement_lead_ins")
_TAILS = english_words("acknowledgement_tails") | english_words("thanks_words")


def acknowledgement(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """A piece that is one acknowledgement phrase, with lead-in and courtesy words only."""
    if piece.asks:
        return None  # "got it?": asked back
    # no look at ``acts.request``: "will" of "will do" reads as "will you ..."; the whole
    # piece being the phrase is what says it asks nothing
    if any(m.possessive for m in piece.lexed.mentions):
        return None  # "Crystal's ...": someone's thing
    words = list(piece.words)
    while len(words) > 1 and words[-1] in _TAILS:
        words.pop()
    while tuple(words) not in _PHRASES:
        if len(words) < 2 or words[0] not in _LEAD_INS:
            return None  # more than a phrase: read by the rules after this one
        words.pop(0)
    return Finding("thanks", piece, "an acknowledgement, not a request")
