"""Wanting to have a thing: "Wang wants to borrow my stapler", "Mark wants to use the ruler",
"Zhang needs to borrow a charger". Said right after a colleague's name, a want whose verb is
one of having or borrowing (``borrow_words``, ``self_taking_verbs``) is that colleague's want of
the thing itself: where the request then takes the thing to a room ("..., take it to the
meeting room", "..., drop it at reception") that colleague is whom it is for, as one said to
need it is. A plain "Wang wants it up on the board" is a wish about the thing, never this.

The reader (``agents.symbolic.reading.room_receiver``) and the runtime's consent guard
(``runtime.recipients``, ``runtime.wanted_own``) decide with this one function, so the guard
lets the hand-over the reader planned go to the colleague named.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english, language

# the want said right after the name: "wants", "needs", and the helping verb's ("would like",
# "might want": ``modal_wants``, ``tentative_wants``), as word tuples, the longest first
_WANTS = tuple(
    sorted(
        {
            *((w,) for w in ("wants", "want", "wanted", "needs", "need", "needed")),
            *(tuple(p.split()) for p in english.entries("modal_wants")),
            *(tuple(p.split()) for p in english.entries("tentative_wants")),
        },
        key=len,
        reverse=True,
    )
)
# the verbs of having the thing ("to borrow", "to use", "to have")
_HAVING = english.words("borrow_words") | english.words("self_taking_verbs")
# the most words a want and its "to <verb>" take
REACH = max(len(w) for w in _WANTS) + 2


def wants_to_have(after: Sequence[str]) -> bool:
    """Whether the folded words ``after`` a name open with a want of having a thing: "wants
    to borrow ...", "needs to use ...", "would like to have ..." (the first ``REACH`` count)."""
    return want_of_having(after) > 0


def want_of_having(after: Sequence[str]) -> int:
    """How many of the folded words ``after`` a name are a want of having a thing ("would
    like to borrow": 4), 0 when they are none."""
    for want in _WANTS:
        n = len(want)
        if tuple(after[:n]) != want or len(after) < n + 2 or after[n] != "to":
            continue
        verb = after[n + 1]
        return n + 2 if verb in _HAVING or bool(language.verb_lemmas(verb) & _HAVING) else 0
    return 0
