"""A thing nobody here has, asked for someone outside the office: "grab a box of aspirin out
of the cabinet for the customer at the till". The outsider rule would offer to bring "it" to
the requester instead, but there is no "it": the office has no such thing, so nothing can be
brought to anyone. The thing is named back as not known here, in words, and nothing moves.

Only a fetch or a making whose words name no item, facility or place of the office counts:
"bring a ruler to the customer" (a ruler the office has) and "take it to the visitor" (a
thing said before) are the outsider rule's, asked about as ever."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language

_BACK_WORDS = english.words("another_one")  # "bring a few for the visitor": of what was said
_ASKED = frozenset({"give", "make"})  # the cue kinds that ask for a thing
_OFFICE_KINDS = frozenset({"item", "facility", "place"})


def thing_not_here(terms: Terms, msg: Message, piece: Piece) -> str | None:
    """The words of the thing the piece asks for when no one in this office has it ("box
    of aspirin"); None when it names the office's own or names nothing."""
    if any(m.kind in _OFFICE_KINDS for m in msg.lexed.mentions):
        return None
    cue = next((m for m in piece.lexed.mentions if m.kind == "cue" and _ASKED & set(m.ids)), None)
    if cue is None:
        return None
    thing = terms.unknown_thing([t.word for t in piece.lexed.tokens[cue.end :]])
    words = thing.split()
    if not words or set(words) <= _BACK_WORDS:
        return None
    if not all(language.lemmas(w) or language.zipf(w) > 0 for w in words):
        return None  # a word no dictionary knows: a name or a typo, asked about as ever
    return thing
