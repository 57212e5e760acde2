"""Whether a piece names one of the speaker's own things: "don't let anyone borrow *my*
stapler today", "nobody take *our* scissors". A wish that keeps the speaker's own thing from
others, then "I need it", says why the thing is kept: the need is the reason for the wish,
answered with it in words, never a new need that would move the thing (``wish``)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.pieces import Piece

_OWN = frozenset({"my", "our"})
_MOST_BETWEEN = 2  # "my *old red* stapler": describing words between the possessive and it


def names_own_thing(piece: Piece) -> bool:
    """Whether an item of the office is named in ``piece`` as the speaker's ("my stapler",
    "our big scissors")."""
    tokens = piece.lexed.tokens
    for m in piece.lexed.mentions:
        if m.kind != "item":
            continue
        for k in range(m.start - 1, max(-1, m.start - 2 - _MOST_BETWEEN), -1):
            if tokens[k].word in _OWN:
                return True
            if tokens[k].after_pause or tokens[k].possessive:
                break
    return False
