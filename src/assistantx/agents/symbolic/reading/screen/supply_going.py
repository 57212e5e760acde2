"""A supply said to be "going": "is there any paper going?", "any tape going spare?". British
"going" (spare) says a thing is there for whoever wants it; asked of the assistant about a thing
a facility of the office keeps for anyone (its supply, the office's data), it is the speaker's
want of one, read as "can I have some paper?" is. A thing only colleagues have stays a question,
answered with who has one and an offer (asking them is the consent rules' part), and "is
anything going on?" names no thing: a question, as before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.pieces import Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms

# what may come before the thing: "is there any", "are there some", "anyone got a spare"
_BEFORE = frozenset(
    {"is", "are", "there", "theres", "any", "some", "a", "an", "spare", "extra", "more"}
    | {"anyone", "anybody", "got", "still", "by", "chance", "yo", "hey", "hi", "oh", "so"}
)
# what may come after "going": "going spare", "going anywhere", "going at all", "please"
_AFTER = frozenset({"spare", "anywhere", "around", "at", "all", "free", "please", "pls", "today"})


def supply_going(terms: Terms, piece: Piece) -> bool:
    """Whether ``piece`` asks whether one of the office's supplies is "going" (to be had)."""
    if piece.acts.later or piece.acts.question is None:
        return False
    words = [t.word for t in piece.lexed.tokens]
    items = [m for m in piece.lexed.mentions if m.kind == "item"]
    if len(items) != 1 or len(items[0].ids) != 1:
        return False
    thing = items[0]
    if words[thing.end : thing.end + 1] != ["going"]:
        return False
    if not all(w in _BEFORE for w in words[: thing.start]):
        return False
    if not all(w in _AFTER for w in words[thing.end + 1 :]):
        return False
    return terms.office.supplier(thing.ids[0]) is not None
