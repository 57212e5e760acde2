"""A comma part of an outside address ("courier my contract to Harlow Council planning
department, Civic Centre, *Water Gardens*, Harlow"): where the message names a service that
sends things out, and a part of its sentence before this one says "to" a place, the parts
from there to the sentence's end that are each a proper name or a numbered line are that
place's address. Such a part is read by no rule of the screen: a word of it that names a
service, a thing or a colleague ("Water", "Print", "Will") is part of a street's or a
building's name, never a request nor a statement; the part stays in the request, whose
destination (reading/destination.py) spans it."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.address_run import address_part, lone_word
from assistantx.agents.symbolic.reading.screen.outsider import sends_out
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms


def outside_address_part(terms: Terms, msg: Message, piece: Piece) -> bool:
    """Whether ``piece`` is one of the comma parts of an outside address, said to its
    sentence's end after the part that says "to" the place."""
    if not _an_address_part(piece):
        return False
    run = _comma_run(msg, piece)
    at = next(n for n, p in enumerate(run) if p is piece)
    before = run[:at]
    # back over the parts before it that are address parts too, to the part that began the
    # destination: it says "to" (the place itself may be lower case: "to the county office")
    opener = next((p for p in reversed(before) if not _an_address_part(p)), None)
    if opener is None or "to" not in opener.words:
        return False
    if not all(_an_address_part(p) for p in run[at:]):
        return False  # "..., Leeds, it has to go today": a clause, so no address to the end
    after = run[run.index(opener) + 1 :]
    if lone_word([p.lexed.tokens for p in after]):
        return False  # "to the tax office, Frank": maybe said to Frank
    return sends_out(terms, msg)


def _an_address_part(piece: Piece) -> bool:
    tokens = piece.lexed.tokens
    names = {
        k
        for m in piece.lexed.mentions
        if m.kind in ("place", "person")
        for k in range(m.start, m.end)
    }
    return address_part(tokens, range(len(tokens)), names)


def _comma_run(msg: Message, piece: Piece) -> list[Piece]:
    """The pieces of ``piece``'s sentence joined to it by commas only, in order."""
    at = next(n for n, p in enumerate(msg.pieces) if p is piece)
    first = last = at
    while first > 0 and _comma_between(msg, msg.pieces[first - 1], msg.pieces[first]):
        first -= 1
    while last + 1 < len(msg.pieces) and _comma_between(
        msg, msg.pieces[last], msg.pieces[last + 1]
    ):
        last += 1
    return msg.pieces[first : last + 1]


def _comma_between(msg: Message, a: Piece, b: Piece) -> bool:
    return msg.text[a.end : b.start].strip() == ","
