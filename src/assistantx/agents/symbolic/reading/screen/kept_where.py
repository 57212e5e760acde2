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
from assistantx.core.wording import is_are, some_or_one

_KEEPING = english.words("kept_where_verbs")
_PRONOUNS = frozenset({"it", "them", "they", "these", "those"})


def kept_where(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if _topic(terms, msg, piece):
        # "clay for the casting trial - where do we keep it?": the thing the question after
        # it is about, named first; no errand of its own
        return Finding("question", piece, "the thing a where-question after it asks about")
    if not _asks_where_kept(piece):
        return None
    items = _items(terms, piece) or _topic_items(terms, msg, piece)
    if len(items) != 1:
        return None
    return Finding(
        "question",
        piece,
        "a question of where a thing is kept, answered in words",
        message=_where_kept(terms, items[0]),
    )


def _asks_where_kept(piece: Piece) -> bool:
    words = content(piece.words)
    return (
        piece.acts.question == "info"
        and words[:1] in (["where"], ["wheres"])
        and bool(set(words) & _KEEPING)
    )


def _items(terms: Terms, piece: Piece) -> list[str]:
    """The thing asked about: the first one named ("the milk for the tea": the milk; what
    follows "for" is what it is for)."""
    named = [m for m in piece.lexed.mentions if m.kind == "item" and len(m.ids) == 1]
    if named:
        return [min(named, key=lambda m: m.start).id]
    return _kept_names(terms, piece)


def _topic(terms: Terms, msg: Message, piece: Piece) -> bool:
    """A piece that only names one thing (no request, no question), followed by a question
    of where "it" is kept."""
    acts = piece.acts
    if acts.request or acts.imperative or acts.question is not None or acts.statement:
        return False
    if len(_items(terms, piece)) != 1:
        return False
    later = [p for p in msg.pieces if p.start >= piece.end]
    return bool(later) and _asks_where_kept(later[0]) and not _items(terms, later[0])


def _topic_items(terms: Terms, msg: Message, piece: Piece) -> list[str]:
    """The thing "it"/"them" stands for, named by the piece just before the question."""
    if not set(piece.words) & _PRONOUNS:
        return []
    before = [p for p in msg.pieces if p.end <= piece.start]
    return _items(terms, before[-1]) if before else []


def _where_kept(terms: Terms, item: str) -> str:
    office = terms.office
    thing, mass = office.item_type(item).name, office.item_type(item).mass
    be = is_are(thing, mass=mass)
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
        one = some_or_one(thing, mass=mass)
        return f"As far as I know, {listed(owners[:4])} {has} {one} at their desk."
    return f"I don't know where the {thing} {be} kept here."


def _at(terms: Terms, facility: Facility) -> str:
    return f"the {facility.name} ({terms.office.location(facility.location).name})"


def _kept_names(terms: Terms, piece: Piece) -> list[str]:
    """ "where do we keep the Clay?": a colleague's name that is also the name of a thing
    here; people are not kept anywhere, so the thing is meant."""
    said = (m.text.lower() for m in piece.lexed.mentions if m.kind == "person")
    return [terms.lex.items[w] for w in said if w in terms.lex.items]
