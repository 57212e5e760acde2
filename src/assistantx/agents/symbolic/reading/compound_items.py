"""Work that needs an item of one kind, its object a compound whose first part names that
kind: "sign this *contract* extension", "stamp the *lease* renewal" ask for the requester's
contract or lease.

The lexicon reads an item's name before a noun the office does not know as the first part of
a compound (``compound_heads``): "the wine list" is a list, not wine. Work that only ever
acts on an item of one property (a paper one signs, a paper one stamps) cannot take a list:
its object is still a paper, and the compound's first part says which. So when such work
names no item, the one item with that property that the requester owns is meant, provided
that item's own name is the first part of a compound in the request. Any other work ("bring
me the wine list", "send my wine list file") is unchanged: the head still names the thing.
Two such items of the requester's, or none, or a first part that names another item, still
ask "which item?".
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core.office import Office


def _names(office: Office, type_id: str) -> set[str]:
    t = office.item_type(type_id)
    return {n.lower() for n in (t.name, *t.synonyms)}


def first_part_item(
    office: Office, mentions: Sequence[Mention], prop: str, requester: str
) -> str | None:
    """The requester's one item with ``prop`` when its name is a compound's first part here
    (a plain word directly followed by another plain word), else None."""
    owned = {
        o.type for o in office.person(requester).owns if getattr(office.item_type(o.type), prop)
    }
    if len(owned) != 1:
        return None
    [type_id] = owned
    names = _names(office, type_id)
    return next(
        (
            type_id
            for a, b in itertools.pairwise(mentions)
            if a.kind == "word"
            and b.kind == "word"
            and b.start == a.end
            and a.ids
            and a.ids[0] in names
        ),
        None,
    )
