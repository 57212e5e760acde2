"""A made thing asked for by where it comes from: "glass of water please, and something from
the vending machine", "grab me something from the coffee machine". A facility that makes one
kind of thing from nothing names it: "something from the vending machine" is a snack, so the
part is read as the product it is (before, it was a statement and the second product was
dropped in silence). A facility that makes several kinds, or none, or makes its thing from an
item ("something from the printer" may be a printout of anything, or a paper left there)
keeps the words as said (the reader asks what is meant). The facilities and their products
are the office's own data.

"something salty", "anything hot": the words that describe what is wanted say only which of
the facility's things, so one kind is that kind; a word that names a party or a place
("something for Wang from ...") is no description and leaves the words as said."""

from __future__ import annotations

import re

from assistantx.core import english
from assistantx.core.office import Office
from assistantx.core.wording import a_thing

_VAGUE = r"(?:something|a\s+thing|summat|sth)"
# "anything from the coffee machine for me?" may ask whether something came; "anything hot
# from the coffee machine" describes what is wanted, so "anything" is vague only when described
_ANY = r"anything"

# The words that are no description of the thing: who it is for or from, whose, where,
# when ("something for Wang from ...", "something of mine from ...").
_NOT_DESCRIBING = sorted(
    {
        *english.entries("prepositions_and_joins"),
        *english.entries("party_prepositions"),
        *english.entries("time_prepositions"),
        *english.entries("determiners"),
        *english.entries("pronouns"),
        *english.entries("object_pronouns"),
        *english.entries("subject_pronouns"),
        "mine",
        "yours",
        "please",
    },
    key=len,
    reverse=True,
)
_WORD = r"(?!(?:{})\b)[a-z][a-z'-]*".format("|".join(re.escape(w) for w in _NOT_DESCRIBING))
# up to three describing words, "sweet", "hot and sweet", "salty, crunchy"
_DESCRIBING = rf"(?:\s+|\s*,\s*)(?:(?:and|or)\s+)?{_WORD}"
_DESCRIBED = rf"(?:{_VAGUE}(?:{_DESCRIBING}){{0,3}}|{_ANY}(?:{_DESCRIBING}){{1,3}})"


class SomethingFrom:
    """The rewrite for one office, its patterns made once (it runs on every message)."""

    def __init__(self, office: Office) -> None:
        self._rewrites: list[tuple[re.Pattern[str], str]] = []
        for facility in office.facilities:
            made = sorted(set(facility.products))
            if len(made) != 1 or not _from_nothing(office, facility.operations, made[0]):
                continue
            names = sorted({facility.name, *facility.synonyms}, key=len, reverse=True)
            said = "|".join(re.escape(n) for n in names if n)
            product = office.item_type(made[0])
            thing = a_thing(product.name, mass=product.mass)
            pattern = rf"\b{_DESCRIBED}(\s+(?:from|out\s+of)\s+(?:the\s+)?(?:{said})\b)"
            self._rewrites.append((re.compile(pattern, re.IGNORECASE), rf"{thing}\1"))

    def __call__(self, text: str) -> str:
        """``text`` with each "something from the <facility>" written as "<a product> from
        the <facility>" where the facility makes exactly one kind of thing from nothing."""
        for pattern, thing in self._rewrites:
            text = pattern.sub(thing, text)
        return text


def _from_nothing(office: Office, operations: tuple[str, ...], product: str) -> bool:
    """Whether the facility makes ``product`` from nothing (a coffee, a snack), not from an
    item of someone's (a printout of a file)."""
    ops = [office.operation(o) for o in operations]
    return any(op.product == product for op in ops) and all(
        op.input is None for op in ops if op.product == product
    )
