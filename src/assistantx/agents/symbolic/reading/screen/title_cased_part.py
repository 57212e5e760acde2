"""A comma part of a sentence written as a title ("..., School of Pharmacy, *King's
Building*", "..., *Roscoe Building*, Oxford Road"): every word capitalised but for a name's
small joining words. People write a clause in sentence case, so a part in title case names
something (a place, a part of an address, an organisation) and goes on the phrase before its
comma; it is never a statement of its own, even where one of its words could be read as a
verb ("Building", "Crossing")."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece

# Small words a place's proper name holds between its capitalised words ("School *of*
# Pharmacy", "Marks *and* Spencer").
_NAME_JOINS = frozenset({"of", "and", "&", "the", "for", "on", "upon", "de", "la"})


def title_cased_part(msg: Message, piece: Piece) -> bool:
    """Whether ``piece`` follows a comma of its sentence and is written in title case."""
    if not msg.text[: piece.start].rstrip().endswith(","):
        return False
    said = piece.text.split()
    capitalised = [w[:1].isupper() or w[:1].isdigit() for w in said]
    # a title's first word is capitalised, and so is every word but a joining one
    return (
        bool(said)
        and capitalised[0]
        and all(c or w.lower() in _NAME_JOINS for c, w in zip(capitalised, said, strict=True))
    )
