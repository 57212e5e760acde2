"""Where the requester says the thing they ask for will come from, in a sentence of its own:
"Need the register for the check. Otto's got the keys so it'll have to come *out of the
cabinet* via him", "... it's kept in the cabinet" (the frames stage, for a task whose
owner no word of the request says).

A place or facility of the office said after "out of", or after "it's (kept) in/at", names
where the thing is kept. An item type exactly one owner keeps there is theirs (a colleague's
belonging is still asked of them as usual; a supply's owner part is the facility); none or
several there say nothing, and whose is asked as before.

"from" names it too, only for a thing read as the requester's own because they give it, no
"my" said: "take him the jump pack from the valet cupboard" is the one kept there, not the
speaker's own (round 272). A thing nobody's said ("bring me the stapler from the meeting
room") is read as anyone's, as before.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.kept_items import items_kept_at
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.office import Office
from assistantx.core.task_schema import Task
from assistantx.memory.names import normalize

_ARTICLES = frozenset({"the", "a", "an", "our", "that"})
_IN = frozenset({"in", "at", "inside"})
_BE = frozenset({"s", "is", "are", "re"})
_SUBJECTS = frozenset({"it", "they", "its", "theyre"})


def kept_where_said(
    office: Office,
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    *,
    taken_from: bool = False,
) -> dict[str, str]:
    """Item type → the one owner part that keeps it at a place the text says the thing
    comes out of or is in (``taken_from``: or is taken from, "from the valet cupboard");
    types kept there by several owners are left out."""
    owners: dict[str, set[str]] = {}
    heads = _facility_heads(office)
    for m in mentions:
        if m.kind in ("facility", "place"):
            kind, where = m.kind, m.ids[0]
        elif m.kind == "word" and m.end - m.start == 1 and tokens[m.start].word in heads:
            kind, where = "facility", heads[tokens[m.start].word]  # "the cabinet"
        else:
            continue
        if not _said_as_where_it_is(tokens, m.start, taken_from=taken_from):
            continue
        for kept in items_kept_at(office, kind, where):
            owners.setdefault(kept.type_id, set()).add(kept.owner)
    return {item: next(iter(who)) for item, who in owners.items() if len(who) == 1}


def _facility_heads(office: Office) -> dict[str, str]:
    """The last word of a facility's name of several words ("cabinet" of "CD cabinet")
    that ends no other facility's name: "out of the cabinet" says that one, here only,
    where the words around it already say it is where a thing is kept."""
    heads: dict[str, set[str]] = {}
    for f in office.facilities:
        for name in (f.name, *f.synonyms):
            words = normalize(name).split()
            if len(words) > 1:
                heads.setdefault(words[-1], set()).add(f.id)
    return {head: next(iter(ids)) for head, ids in heads.items() if len(ids) == 1}


def _said_as_where_it_is(tokens: Sequence[Token], start: int, *, taken_from: bool) -> bool:
    """ "(come) out of the cabinet", "it's (kept) in the cabinet" (``taken_from``: also
    "from the cabinet")."""
    k = start
    while k > 0 and tokens[k - 1].word in _ARTICLES:
        k -= 1
    words = [t.word for t in tokens[max(0, k - 4) : k]]
    if words[-2:] == ["out", "of"] or (taken_from and words[-1:] == ["from"]):
        return True  # "out of the cabinet", "the jump pack from the valet cupboard"
    if not words or words[-1] not in _IN:
        return False
    rest = words[:-1]
    if rest and rest[-1] == "kept":
        rest = rest[:-1]
    if rest and rest[-1] in _BE:
        rest = rest[:-1]
    return bool(rest) and rest[-1] in _SUBJECTS


def owned_as_said(
    task: Task,
    kept: dict[str, str],
    requester: str = "",
    *,
    mine_said: bool = True,
    kept_from: dict[str, str] | None = None,
) -> Task:
    """A fetch of an item whose owner the request leaves unsaid, from the one owner that
    keeps it where the text says it is. The requester's own read only because they give it
    ("take him the jump pack", with no "my" said: ``mine_said`` False) is that one too where
    the place it is taken from keeps someone else's (``kept_from``): "from the valet
    cupboard" says which it is."""
    if task.kind != "transfer" or task.item is None or task.source:
        return task
    defaulted = bool(requester) and task.owner == requester and not mine_said
    if task.owner is not None and not defaulted:
        return task
    owner = ((kept_from or kept) if defaulted else kept).get(task.item)
    if owner is None or owner == task.recipient or owner == task.owner:
        return task
    return task.model_copy(update={"owner": owner})
