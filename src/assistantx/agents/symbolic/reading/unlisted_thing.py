"""A thing asked for from a facility that the office does not list: "bring me 50 ml of
chloroform from the chem store", where the store only makes ethanol. The word that heads the
object, right before "from/at/in/out of" the facility, names the thing; when it is no item of
the office (no mention of one) and no everyday filler ("one", "some"), it is that unlisted
thing, declined by name, never swapped for what the facility makes or keeps, unless it is a
variety of the one thing the facility makes ("a flat white from the coffee machine":
``variety_of``)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.categories import categories, is_member
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core import english
from assistantx.core.office import Office

_COMMON = english.words("common")
_FROM_WORDS = frozenset({"from", "at", "in", "of", "out"})


def unlisted_thing(mentions: Sequence[Mention]) -> tuple[str, str] | None:
    """The unlisted thing asked for from a facility and that facility's id, or None."""
    for n, m in enumerate(mentions):
        if m.kind != "facility" or n < 2:
            continue
        k = n - 1
        while k >= 0 and mentions[k].kind == "word" and mentions[k].ids[0] in _FROM_WORDS:
            k -= 1  # "out of the store", "from the store"
        if k == n - 1 or k < 0:
            continue
        head = mentions[k]
        if head.kind != "word" or head.possessive:
            continue
        word = head.ids[0]
        if word in _COMMON or not word.isalpha() or len(word) < 3:
            continue
        return head.text.lower(), m.ids[0]
    return None


def variety_of(
    office: Office, mentions: Sequence[Mention], facility_id: str
) -> tuple[tuple[str, ...], str] | None:
    """ "a chocolate bar from the vending machine", "a flat white from the coffee machine": an
    unlisted thing asked for from a facility that makes one product and keeps nothing, where
    the thing and the product are of one kind of the categories' table (a snack, a hot
    drink): the words that named it and the product's name, so the request is read as for
    the product. A thing of no shared kind ("chloroform" from a store that makes ethanol) is
    still declined by name."""
    facility = office.facility(facility_id)
    if len(facility.products) != 1 or facility.supplies:
        return None
    product = office.item_type(facility.products[0])
    at = next(
        (n for n, m in enumerate(mentions) if m.kind == "facility" and m.ids == (facility_id,)),
        None,
    )
    if at is None:
        return None
    k = at - 1
    while k >= 0 and mentions[k].kind == "word" and mentions[k].ids[0] in _FROM_WORDS:
        k -= 1
    if k == at - 1:
        return None
    said: list[str] = []
    while k >= 0 and len(said) < 3 and _plain_word(mentions[k]):
        said.insert(0, mentions[k].ids[0])
        k -= 1
    for n in range(len(said)):  # the longest phrase first: "chocolate bar", then "bar"
        if _same_kind(" ".join(said[n:]), (product.name, *product.synonyms)):
            return tuple(said[n:]), product.name
    return None


def _plain_word(m: Mention) -> bool:
    word = m.ids[0] if m.ids else ""
    return m.kind == "word" and not m.possessive and word.isalpha() and word not in _COMMON


def _same_kind(thing: str, product_names: Sequence[str]) -> bool:
    """Whether the thing and one of the product's names are of one category of the table."""
    return any(
        is_member(c, thing) and any(is_member(c, p) or p in c.names for p in product_names)
        for c in categories()
    )
