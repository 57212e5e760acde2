"""Thanks: "thanks for the pen!", answered in words; thanks to pass on ("say thanks to Wang
for the pen") is the requester's to give; approval ("Love it.") is answered in words too.

The one thing thanked for is kept as context (``THANKED``): "thanks for the milk earlier! could
you bring a bit more" asks for more of it (``rewrites``); the thanks alone moves nothing."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.statement import stated_products
from assistantx.agents.symbolic.reading.screen.terms import Terms

THANKED = "thanked:"  # the context a thanks leaves: the one item type thanked for


def thanks(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    act = piece.acts.thanks
    if act is None:
        return None
    if act.relay:
        people = terms.named(piece.lexed, "person")
        who = terms.office.person(people[0]).name if len(people) == 1 else "them"
        message = f"I only pass on messages as part of an errand, so please tell {who} yourself."
        return Finding("thanks", piece, "thanks to pass on, not a request", message=message)
    if act.approval:  # "Love it.": a reaction to what was said
        return Finding("thanks", piece, "approval, not a request", message="Glad you like it!")
    items = list(dict.fromkeys([*terms.named(piece.lexed, "item"), *stated_products(terms, piece)]))
    thanked = (f"{THANKED}{items[0]}",) if len(items) == 1 else ()
    return Finding(
        "thanks", piece, "thanks, not a request", message="You're welcome!", context=thanked
    )
