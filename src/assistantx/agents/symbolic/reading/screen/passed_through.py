"""A way of handing a thing to a facility, not a service of its own: "pls feed this through
the shredder", "send my deed through the scanner", "run it thru the laminator". A verb that
would name a service the office lacks ("feed") whose object goes *through* one of the
office's facilities asks for that facility's own service on the thing; the frame reads
which (``_kinds``: a facility said after "through"), so the verb is not declined.

"can you walk through the copy room" (no facility after "through") is declined or read as
before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_THROUGH = english.words("through_prepositions")


def through_a_facility(terms: Terms, text: str) -> bool:
    """Whether ``text`` says something goes through one of the office's facilities."""
    tokens = terms.lex.tokens(text)
    for m in terms.lex.scan(tokens):
        if m.kind != "facility":
            continue
        k = m.start - 1
        while k >= 0 and tokens[k].word in DETERMINERS:
            k -= 1  # "through *the* scanner"
        if k >= 0 and tokens[k].word in _THROUGH:
            return True
    return False
