"""Where a thing is kept: "where do we keep the clay?", "where's the modelling clay kept?",
"where do we store the sample trays?": a question for information, answered in words from
what the office file says (the facilities that keep it for anyone, where each owner's one is
kept, the facility that makes it), or that it is not known. Asking where a thing lives is not
asking for it: no "Shall I bring you one?" (that is left to "where can I get one?")."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms, listed
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english
from assistantx.core.office import Facility
from assistantx.core.wording import is_are

_WHERE = frozenset({"where", "wheres"})
_KEEPING = english.words("kept_where_verbs")


def kept_where(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.question != "info":
        return None
    words = content(piece.words)
    if words[:1] not in (["where"], ["wheres"]) or not set(words) & _KEEPING:
        return None
    items = terms.named(piece.lexed, "item") or _kept_names(terms, piece)
    if len(items) != 1:
        return None
    return Finding(
        "question",
        piece,
        "a question of where a thing is kept, answered in words",
        message=_where_kept(terms, items[0]),
    )


def _where_kept(terms: Terms, item: str) -> str:
    office = terms.office
    thing = office.item_type(item).name
    be = is_are(thing)
    keeping = [f for f in office.facilities if any(s.type == item for s in f.supplies)]
    if not keeping:  # where each owner's one is kept, when it is not on their desk
        keepers = (office.keeper(p, item) for p in office.owners_of(item, known_only=True))
        keeping = list({f.id: f for f in keepers if f is not None}.values())
    if keeping:
        return f"The {thing} {be} kept at {listed([_at(terms, f) for f in keeping])}."
    makers = [f for f in office.facilities if item in f.products]
    if makers:
        return f"The {_at(terms, makers[0])} makes the {thing}."
    owners = [office.person(p).name for p in office.owners_of(item, known_only=True)]
    if owners and office.item_type(item).physical:
        has = "has" if len(owners) == 1 else "each have"
        return f"As far as I know, {listed(owners[:4])} {has} one at their desk."
    return f"I don't know where the {thing} {be} kept here."


def _at(terms: Terms, facility: Facility) -> str:
    return f"the {facility.name} ({terms.office.location(facility.location).name})"


def _kept_names(terms: Terms, piece: Piece) -> list[str]:
    """ "where do we keep the Clay?": a colleague's name that is also the name of a thing
    here; people are not kept anywhere, so the thing is meant."""
    said = (m.text.lower() for m in piece.lexed.mentions if m.kind == "person")
    return [terms.lex.items[w] for w in said if w in terms.lex.items]
