"""A kind of a made thing the office names by its plain name only: "a flat white" where the
coffee machine makes coffee, "a green tea" said as "a chai" where the urn makes tea.

The office file names what its machines make ("coffee", with the synonyms it chose); a kind
it did not list is no word of the office, and the request was declined as a thing nobody
here has ("Sorry, there is no flat white in this office"), though a careful assistant would
offer the coffee the office makes. The package's table of general English things
(``data/categories.yaml``) says which things are kinds of a drink; where one of them is asked
for and the office makes the thing it is a kind of, the screen asks: "I can get a coffee made
here, but a flat white is not something this office makes. Shall I get you a coffee
instead?", a yes reading the request with the office's name in its place, a no doing
nothing.

Never read so: a kind the office names itself (the default office's "latte" is its coffee),
a kind said before another thing's name ("the flat white envelope": what the envelope is
like), one said as someone's ("Wang's latte": theirs, not a drink to make), and a thing of
the office's own whose name holds the words ("the green tea caddy" where the caddy is an
item), and a kind said beside the office's own name for the thing ("a coffee, flat white if
poss": the coffee asked for, as before), or beside the machine that makes it ("a flat white
from the coffee machine": its coffee, as before). Only a kind of the thing itself is
offered, never a thing of the same sort ("a coffee" where the urn makes only tea stays
declined).
"""

from __future__ import annotations

from dataclasses import dataclass

from assistantx.agents.symbolic.reading.categories import kinds_of
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.variant import OFFICE_KINDS, span_of
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language
from assistantx.core.wording import a_thing


@dataclass(frozen=True)
class _Kind:
    item_type: str  # the office's product it is a kind of
    name: str  # the kind, as the table names it (singular)
    said: tuple[Token, ...]  # the kind's words as written


def kind_of_product(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """The screen's rule: a request piece asking for a kind of a product the office makes
    under its plain name only."""
    del requester  # the earlier rules of the table took the pieces that ask nothing
    found = _kind(terms, msg, piece)
    if found is None:
        return None
    span = span_of(msg, piece, found.said)
    if span is None:
        return None
    kind = terms.office.item_type(found.item_type)
    typed = msg.text[span[0] : span[1]]
    plain = a_thing(kind.name, mass=kind.mass)
    several = found.said[-1].word != found.name.split()[-1]  # "two flat whites"
    return Finding(
        "instead",
        piece,
        f"a kind of {kind.name} the office does not make: {typed}",
        message=(
            f"I can get {plain} made here, but {a_thing(found.name)} is not something this "
            f"office makes. Shall I get {plain} instead?"
        ),
        offer=f"{msg.text[: span[0]]}{kind.name}{'s' if several else ''}{msg.text[span[1] :]}",
    )


def _kind(terms: Terms, msg: Message, piece: Piece) -> _Kind | None:
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    taken = {k for m in mentions if m.kind in OFFICE_KINDS for k in range(m.start, m.end)}
    items_at = {m.start: m for m in mentions if m.kind == "item"}
    words = [t.word for t in tokens]
    named = {i for m in msg.lexed.mentions if m.kind == "item" for i in m.ids}
    # "a flat white from the coffee machine": what that machine makes, asked of it by kind
    named |= {
        product
        for m in msg.lexed.mentions
        if m.kind == "facility"
        for f in m.ids
        for product in terms.office.facility(f).products
    }
    for item_type, kinds in _kinds_made_here(terms):
        if item_type in named:
            continue  # "a coffee, flat white if poss": the office's own, a wish of which
        for kind in sorted(kinds, key=lambda k: -len(k.split())):
            said = kind.split()
            n = len(said)
            for start in range(len(words) - n + 1):
                end = start + n
                if not _same(words[start:end], said):
                    continue
                if taken & set(range(start, end)):
                    continue  # a word of the office's own: its own names read it
                if end in items_at:
                    continue  # "the flat white envelope": what another thing is like
                if start > 0 and tokens[start - 1].possessive:
                    continue  # "Wang's latte": someone's own, no drink to make
                return _Kind(item_type, kind, tokens[start:end])
    return None


def _kinds_made_here(terms: Terms) -> list[tuple[str, frozenset[str]]]:
    """Each product the office makes with the kinds of it the table knows and the office
    does not name itself."""
    out: list[tuple[str, frozenset[str]]] = []
    for t in terms.office.item_types:
        if terms.office.making(t.id) is None:
            continue
        kinds = frozenset(k for name in (t.name, *t.synonyms) for k in kinds_of(name))
        unnamed = frozenset(k for k in kinds if k not in terms.lex.items)
        if unnamed:
            out.append((t.id, unnamed))
    return out


def _same(typed: list[str], kind: list[str]) -> bool:
    """The kind's words as typed, its last one also as a plural ("two lattes")."""
    if typed[:-1] != kind[:-1]:
        return False
    last = typed[-1]
    return last == kind[-1] or language.fold(last) in (kind[-1] + "s", kind[-1] + "es")
