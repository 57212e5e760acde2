"""Thanks: "thanks for the pen!", answered in words; thanks to pass on ("say thanks to Wang
for the pen") is the requester's to give; approval ("Love it.") is answered in words too."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms


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
    return Finding("thanks", piece, "thanks, not a request", message="You're welcome!")
