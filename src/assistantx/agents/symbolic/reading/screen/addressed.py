"""A message whose only words left are the names of the colleagues it is said to: "Dang, I
left my stapler at home", "cheers for the book, Yang!", "thanks for the pen, Lee and Bo".

A name set off at either end of a message that otherwise asks nothing (thanks, a statement)
is an address (a vocative): it says whom the words are for, not whom to find. So it needs no
resolving: a name two colleagues share, a name nobody has ("Bob") or a name that is also a
word is answered with the rest in words, never asked about. A name inside a request
("thanks, and can you bring Yang's book?") stays in the request and is still asked about."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Spoken
from assistantx.agents.symbolic.reading.screen.pieces import Piece

# Words that join the names of several people addressed at once ("Lee and Bo", "Lee & Bo").
_JOINERS = frozenset({"and", "&", "n"})


def only_addressed(spoken: Spoken) -> bool:
    """Whether every piece the screen kept is an address at the message's start or end, and
    some other piece was answered in words."""
    kept, pieces = spoken.kept, spoken.msg.pieces
    if not kept or len(pieces) < 2 or not spoken.live:
        return False
    ends = (pieces[0], pieces[-1])
    return all(any(p is e for e in ends) and _address(p) for p in kept)


def _address(piece: Piece) -> bool:
    """Whether ``piece`` is one or more names and nothing else: a colleague's name (any
    colleague who answers to it, however many), or a capitalised word the office does not
    know (a name all the same), joined by "and"."""
    acts = piece.acts
    if acts.request or acts.imperative or acts.question is not None:
        return False
    tokens = piece.lexed.tokens
    named = [False] * len(tokens)
    for m in piece.lexed.mentions:
        if m.possessive:
            return False  # "Yang's": someone's thing, not someone spoken to
        if m.kind == "person" or (m.kind == "word" and tokens[m.start].text[:1].isupper()):
            named[m.start : m.end] = [True] * (m.end - m.start)
    if not any(named):
        return False
    return all(n or t.word in _JOINERS for n, t in zip(named, tokens, strict=True))
