"""Left behind: "my phone's on 2% and I left my cable at home": the speaker's own thing is
not here, said as a fact beside why it is wanted now. With nothing asked beside it, a thing a
colleague could lend or a cupboard keeps is offered ("As far as I know, Dang Hao and Zhou Yan
have a data cable. Shall I bring you one?"), never fetched on the statement alone and never
only noted. Said alone ("I forgot my cable", "gosh, I left my stapler at home") it is news,
noted as before; so is a thing nobody lends (a lunch), or one left at a place in the office
("I left my stapler in the meeting room": where it is)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.screen.terms import Terms, who_has
from assistantx.core import english, wording

_LEFT = english.words("left_behind_verbs") - {"dropped", "put"}
_SUBJECTS = english.words("left_behind_subjects")
_OUTSIDE = english.words("home_nouns") | english.words("outside_containers")
_AT = english.words("lack_place_openers") | {"on"}
_JOINS = frozenset({"and", "so", "but"})


def left_behind(before: Sequence[str], after: Sequence[str]) -> bool:
    """Whether the words around "my <thing>" say the speaker left it outside the office:
    "... and I left | my cable | at home", "I forgot | my pass |" (nothing after)."""
    if len(before) < 2 or before[-1] not in _LEFT or before[-2] not in _SUBJECTS:
        return False
    rest = list(after)
    while rest and rest[-1] in ("today", "again", "lol", "this", "morning"):
        rest.pop()
    if not rest:
        return True
    return rest[0] in _AT and any(w in _OUTSIDE for w in rest[1:4])


def situation_said(before: Sequence[str]) -> bool:
    """Whether a clause of the speaker's situation stands before "and I left ..." ("my
    phone's on 2% and I left my cable at home", "laptop nearly dead and I forgot my cable"):
    why the thing is wanted now. Alone, or after an exclamation or a name ("gosh, I left my
    stapler at home", "Dang, ..."), it is news, answered in words."""
    return len(before) >= 5 and before[-3] in _JOINS


def lend_offer(terms: Terms, item: str, requester: str) -> tuple[str, str, str] | None:
    """(what the office knows of one, the request a yes carries out, the question) for a
    thing the speaker left behind, or None where nobody here could lend one."""
    t = terms.office.item_type(item)
    if t.kind != "belonging":
        return None  # a lunch, a document: nobody else's will do
    a_thing = wording.a_thing(t.name, mass=t.mass)
    supplier = terms.office.supplier(item)
    owners = [o for o in terms.office.owners_of(item, known_only=True) if o != requester]
    if supplier is not None:
        known = f"{wording.there_is(t.name, mass=t.mass)} in the {supplier.name}."
    elif owners:
        names = [terms.office.person(o).name for o in owners[:4]]
        known = who_has(names, a_thing)
    else:
        return None
    one = wording.some_or_one(t.name, mass=t.mass)
    return known, f"bring me {a_thing}", f"Shall I bring you {one}?"
