"""What a product asked for is made from, when the request does not say it as a paper:
"get a spare key cut for my car" (the key machine cuts a spare key *from a car key*), "need
some plates pressing, the reg's on the job card" (the press makes plates from a job card).

A product that one of the office's operations makes from a physical item names that
operation (``TaskReader.made``); the operation still needs its input. When the clause names
an item of that input type, that item is it; otherwise the requester's own one is, if they
own exactly one item of that type (a spare key is cut from one's own key). Two of theirs, or
none, leave the input unsaid, so the request is asked about as before; another person's
item is never taken as the input unless the clause names it.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core.office import Office


def input_of_product(
    office: Office,
    products: Sequence[Mention],
    named: Sequence[Mention],
    makers: Mapping[str, str],
    requester: str,
) -> tuple[Mention, bool] | None:
    """The input the first product's operation works on, and whether it is the requester's
    own one (not said in the clause); None when it cannot be told."""
    op_id = next((makers[p.id] for p in products if p.id in makers), None)
    if op_id is None:
        return None
    wanted = office.operation(op_id).input
    if wanted is None:
        return None
    said = [m for m in named if m.kind == "item" and m.id == wanted]
    if said:
        return said[0], False
    mine = [o for o in office.person(requester).owns if o.type == wanted]
    if len(mine) != 1:
        return None
    return Mention("item", -1, -1, (wanted,)), True
