"""Wish: "keep everyone away from Mao's seal", "nobody take my mug", "I wish it were
warmer": answered in words; nothing is moved. After a wish that keeps the speaker's own thing
from others, "I need it" is why (``own_kept``), answered with the wish, not a new need."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.covert import kept_in_the_dark
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.own_kept import names_own_thing
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.still_needed import still_needed
from assistantx.agents.symbolic.reading.screen.terms import Terms


def wish(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.world_wish:
        return Finding(
            "wish",
            piece,
            "a wish about the place, not a request",
            message="Noted; that is not something I can change.",
        )
    if msg.keeping and still_needed(piece):
        # "don't let anyone borrow my stapler today, I need it": why it is kept from others
        return Finding("wish", piece, "the speaker needs their own thing: why the wish")
    if not piece.acts.wish:
        return None
    if kept_in_the_dark(piece.words) and any(p is not piece and p.acts.request for p in msg.pieces):
        return None  # "grab Pat's mug, nobody will know": a request kept from the owner
    msg.keeping = msg.keeping or names_own_thing(piece)
    things = terms.named(piece.lexed, "item")
    what = f"the {terms.office.item_type(things[0]).name}" if len(things) == 1 else "anything"
    return Finding(
        "wish",
        piece,
        "a wish about other people, not a request",
        message=(
            f"Understood: I won't move or hand out {what} unless its owner asks me to. "
            "I can't keep people away from things, though."
        ),
    )
