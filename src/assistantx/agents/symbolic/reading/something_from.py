"""A made thing asked for by where it comes from: "glass of water please, and something from
the vending machine", "grab me something from the coffee machine". A facility that makes one
kind of thing from nothing names it: "something from the vending machine" is a snack, so the
part is read as the product it is (before, it was a statement and the second product was
dropped in silence). A facility that makes several kinds, or none, or makes its thing from an
item ("something from the printer" may be a printout of anything, or a paper left there)
keeps the words as said (the reader asks what is meant). The facilities and their products
are the office's own data."""

from __future__ import annotations

import re

from assistantx.core.office import Office
from assistantx.core.wording import a_thing

_VAGUE = r"(?:something|a\s+thing|summat|sth)"


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
            pattern = rf"\b{_VAGUE}(\s+(?:from|out\s+of)\s+(?:the\s+)?(?:{said})\b)"
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
