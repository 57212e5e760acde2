"""A need, then where the thing comes from said as putting it down at the one in need's place:
"Mark needs a ruler, leave mine on his desk", "Zhang needs a stapler, put Wang's on her desk".

The request after the need names the thing (whose it is) and the place of the one who needs
it; it is how the need is met, one errand. "Leave"/"put" are no task words of the lexicon, so
after a comma they ran on in the need's clause, and the need's "a ruler" (anyone's) and the
request's "mine" were read as two rulers for Mark (two hand-overs, a wrong physical action).
A verb of putting down that opens a comma's clause and puts its thing at a person's own place
("on his desk", "at Will's desk", "in my office": ``core.receiving_place``) starts a request
of its own; the need's hand-over then gives way to it as it does for "give him mine"."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english
from assistantx.core.receiving_place import MEET_AT, PLACE_PRONOUNS, PLACE_WORDS

_PUTTING = english.words("putting_verbs")
_OWN = frozenset({"my", "our"})
_REACH = 8  # "leave my spare one on his desk": the words from the verb to the place


def puts_at_someones_place(mentions: Sequence[Mention], n: int, tokens: Sequence[Token]) -> bool:
    """Whether mention ``n`` is a verb of putting down whose clause puts its thing at a
    person's own place ("leave mine on his desk")."""
    if n >= len(mentions):
        return False
    start = mentions[n].start
    if tokens[start].word not in _PUTTING:
        return False
    after = tokens[start + 1 : start + 1 + _REACH]
    for k, (a, b, c) in enumerate(zip(after, after[1:], after[2:], strict=False)):
        if k and (b.opens or a.opens):
            return False  # the next sentence
        whose = b.word in PLACE_PRONOUNS or b.word in _OWN or b.possessive
        if a.word in MEET_AT and whose and c.word in PLACE_WORDS:
            return True
    return False
