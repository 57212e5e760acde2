"""A thing asked for from a facility by the head noun of one of its supplies' names ("a blade
from the cupboard" where the cupboard keeps "scalpel blades", "a battery from stores" where
it keeps "AA batteries"): the supply's name ends in that noun, so the thing asked is one of
them, matched by its lemma (blade/blades, battery/batteries, knife/knives). Read as that
supply, never "there is no blade ... it has scalpel blades". Only where exactly one of the
facility's supplies and products is so headed; a word that is only a modifier of a name ("a
cable" where it keeps "cable ties") is no such thing, and is declined by name as before."""

from __future__ import annotations

from collections.abc import Iterable

from assistantx.core import language
from assistantx.core.office import Office


def headed_supply(office: Office, thing: str, facility_id: str) -> str | None:
    """The name of the one supply or product of the facility whose names end in the noun
    ``thing`` names (its lemma), or None."""
    said = _noun_lemmas(thing)
    if not said:
        return None
    facility = office.facility(facility_id)
    kept = [*facility.products, *(s.type for s in facility.supplies)]
    found = {
        type_id
        for type_id in kept
        for name in _names(office, type_id)
        if len(name.split()) > 1 and _noun_lemmas(name.split()[-1]) & said
    }
    return office.item_type(found.pop()).name if len(found) == 1 else None


def _names(office: Office, type_id: str) -> Iterable[str]:
    item = office.item_type(type_id)
    return (language.fold(n) for n in (item.name, *item.synonyms))


def _noun_lemmas(word: str) -> set[str]:
    """The nouns ``word`` is a form of (itself where the dictionary knows it as a noun)."""
    nouns = set(language.lemmas(word).get("NOUN", ()))
    return nouns | {word} if nouns else set()
