"""A vessel the office lists as an item, said of or from a facility that makes one poured
product: "a cup of the urn", "a mug from the coffee machine please". The cup is an office
item, so the reader fetched a cup; but "a cup of the urn" asks for what the urn pours, as "a
cup of tea" would, and "a mug from the coffee machine" for its coffee. The phrase is said
again as the vessel of that product ("a cup of tea"), which the later stages read as the
product made for the speaker.

Only an indefinite vessel ("a", "an", "another", "one", a number: never "the mug from the
coffee machine", a mug standing there, nor "my cup"), whose word the office reads as an item
and ``vessel_nouns`` lists, right before "of"/"from" and a facility that makes exactly one
product, keeps nothing, and whose product is poured (a word of its names in
``pourable_words``; ``unlisted_thing.vessel_of`` reads a vessel the office does not list the
same way). A cup from a room ("a cup from the kitchenette") or from a machine of printouts
reads as before. Nothing here knows an office's words: they come from its file.
"""

from __future__ import annotations

import re

from assistantx.core import english, language
from assistantx.core.office import Office

_VESSELS = english.words("vessel_nouns")
_POURABLE = english.words("pourable_words")
# what makes the vessel one of any: "a", "another", "one", "2"
_ANY = r"(?:a|an|another|one|\d+)"


class PouredVessel:
    """The rewrite for one office: its listed vessels and its machines of one poured thing."""

    def __init__(self, office: Office, item_words: frozenset[str]) -> None:
        poured: dict[str, str] = {}
        for f in office.facilities:
            if len(f.products) != 1 or f.supplies:
                continue
            product = office.item_type(f.products[0])
            names = (product.name, *product.synonyms)
            if not any(w in _POURABLE for name in names for w in language.words(name)):
                continue
            for name in (f.name, *f.synonyms):
                poured.setdefault(name.lower(), product.name)
        # "a cuppa from the urn": a vessel word that is the drink itself already says it
        vessels = sorted((_VESSELS - _POURABLE) & item_words, key=len, reverse=True)
        self._product = poured
        machines = sorted(poured, key=len, reverse=True)
        self._pattern = (
            re.compile(
                rf"\b(?P<head>{_ANY}\s+(?:{'|'.join(map(re.escape, vessels))}))\s+(?:of|from)\s+"
                rf"(?:the\s+)?(?P<machine>{'|'.join(map(re.escape, machines))})\b",
                re.IGNORECASE,
            )
            if poured and vessels
            else None
        )

    def __call__(self, text: str) -> str:
        if self._pattern is None:
            return text

        def product(m: re.Match[str]) -> str:
            return f"{m.group('head')} of {self._product[m.group('machine').lower()]}"

        return self._pattern.sub(product, text)
