"""A service of the office told in the past of the speaker's own thing, beside a request for
something else: "gloves from stores when you get a chance. shredded mine on a wire rope this
morning", "a badge from reception pls, laminated the old one wrong". The past verb is what
happened to the speaker's own one (why they ask for a new one), not news that what was asked
for is had already: read as a withdrawal, the gloves were dropped ("OK, I've dropped that
request"). Only where nothing before it asks for that same service: "shred my old drafts.
actually shredded them already" still withdraws the shredding."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import language

# What the past verb is done to: the speaker's own thing ("mine", "my old one", "the old one").
_OWN = frozenset({"mine", "my", "our", "ours", "the", "it", "one"})
# How far after the verb its object is looked for ("shredded *mine*", "laminated my *old* one").
_OBJECT_REACH = 3


def past_service_reason(terms: Terms, msg: Message, piece: Piece) -> bool:
    """Whether ``piece`` tells a past form of one of the office's services done to the
    speaker's own thing while no piece before it asks for that service."""
    words = content(piece.words)
    services = terms.service_lemmas
    for n, x in enumerate(words):
        done = language.verb_lemmas(x) & services
        if not done or not language.is_past_verb(x) or x in done:
            continue  # not a service's verb, or its plain form ("print", "cut")
        if not set(words[n + 1 : n + 1 + _OBJECT_REACH]) & _OWN:
            continue
        earlier = [w for p in msg.pieces if p.end <= piece.start for w in p.words]
        if any(language.verb_lemmas(w) & done or w in done for w in earlier):
            return False  # "shred my drafts. shredded them already": the same service
        return True
    return False
