"""Ordering from outside is not offered: "order us some sandwiches for the meeting", "buy me
a ruler", "purchase a calculator for the new starter". The robot buys nothing and places no
orders, so a request whose verb buys (``purchase_verbs``) is declined in words when what it
names is a thing of the office that no machine of the office makes and no cupboard supplies:
read as an errand, "sandwiches" was taken for a colleague's lunch ("Whose lunch do you
mean?") and "a ruler" was borrowed from a colleague. A product the office makes or supplies
("buy me a tea" where a kettle makes tea, "order some paper" from the stationery cupboard)
is got here as before, unless the order names a seller outside as where it comes from ("order
more paper from the supplier": placed outside, declined); a thing the office has no word for
("order me a pizza") is left to the rules that say the office has none."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_BUYING = english.words("purchase_verbs")


def _got_here(terms: Terms, type_id: str) -> bool:
    """Whether the office itself makes or supplies things of ``type_id``."""
    office = terms.office
    return office.making(type_id) is not None or office.supplier(type_id) is not None


def _from_a_seller(words: list[str]) -> bool:
    """ "(order 20 more reeds) from the supplier", "from a wholesaler", "off the website":
    where the order comes from is a seller outside, so it is placed outside even where a
    cupboard of the office keeps such things."""
    for n, w in enumerate(words):
        if w not in ("from", "off", "on", "via"):
            continue
        rest = [x for x in words[n + 1 : n + 4] if x not in _DETERMINERS]
        if rest[:1] and rest[0] in _SELLERS:
            return True
    return False


_SELLERS = english.words("outside_sellers")
_DETERMINERS = frozenset({"the", "a", "an", "our", "your", "their", "that", "this", "usual"})


def ordering(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del msg, requester
    if not (piece.acts.request or piece.acts.imperative):
        return None
    verb = piece.verb_at(terms.en.lead_in)
    tokens = piece.lexed.tokens
    if verb >= len(tokens) or tokens[verb].word not in _BUYING:
        return None
    if tokens[verb].word in terms.service_verbs:
        return None  # an office's own service called "book" (a room booked here)
    things = [m for m in piece.lexed.mentions if m.kind == "item" and m.start > verb]
    if not things:
        return None
    outside = _from_a_seller([t.word for t in tokens[verb + 1 :]])
    if not outside and any(_got_here(terms, t) for m in things for t in m.ids):
        return None
    return Finding(
        "unsupported",
        piece,
        "ordering from outside",
        message=(
            "Sorry, I can't order things: I can't buy anything or place orders outside the "
            "office. I only fetch things here and run the office's own services. I did nothing."
        ),
    )
