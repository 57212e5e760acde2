"""A thing taken to a room and brought back is the work that room's facility does on it:
"my wax-up is ready to cast, could you take it to the casting room and bring it back after?",
"take my lunch to the kitchenette and back", "take my document to the copy room, then back to
me".

The robot hands things to people, never to rooms, so "take X to <room>" alone asks who there
receives it. But a thing that comes back ("bring it back", "and back", "then back to me") was
not meant to stay with anyone there: it went for what the room is for. When a facility at that
room runs an operation that takes this kind of thing (the one whose operation takes it, read
from the office's own data), the errand is that operation on the thing, and the thing (or its
product) comes back to its owner as with any service. It is said as "<operation verb> X",
which the reader already reads so.

Left as said: no word of the return ("take my mug to the kitchen": who there gets it), a thing
no operation there takes ("take my mug to the kitchenette and back": nothing to do to a mug),
several operations there that take it (nothing decides which), and a person after "to"
("take it to the casting room for Robin" has no return; "to Robin" is no room).
"""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core.office import Office

_WORD = r"[^\W\d_][\w'-]*"
# "take it to", "bring my lunch over to", "run these down to": the carrying and the thing
_CARRY = (
    r"\b(?:take|bring|carry|run|drop|pop)\s+"
    rf"(?P<thing>it|them|this|these|(?:my|our|this|these|the)\s+(?:{_WORD}\s+){{0,3}}?{_WORD})"
    r"\s+(?:(?:over|down|up|along|round)\s+)?(?:to|into)\s+(?:the\s+|our\s+)?"
)
# the thing's return right after the room: "and bring it back (after)", "and back", ", then
# back to me", "and then get them back to me"
_BACK = (
    r"\s*(?:,\s*)?(?:and\s+|then\s+|,\s*)+"
    r"(?:(?:bring|get|send|fetch|have)\s+(?:it|them)\s+)?back"
    r"(?:\s+to\s+me)?(?:\s+(?:after|afterwards|again|later|when\s+(?:it's|they're)\s+done))?\b"
)

_PRONOUNS = frozenset({"it", "them", "this", "these"})


def _rooms(office: Office) -> dict[str, str]:
    """Every name of a room, lower case → its location id (longest first, so "copy room"
    wins over a shorter name inside it)."""
    names = office.place_names()
    return dict(sorted(names.items(), key=lambda kv: -len(kv[0])))


def _work_there(office: Office, room: str, types: set[str]) -> str | None:
    """The verb of the one operation a facility at ``room`` does on a thing of ``types``."""
    ops = {
        op_id
        for f in office.facilities
        if f.location == room
        for op_id in f.operations
        if office.operation(op_id).input in types and office.operation(op_id).verbs
    }
    if len(ops) != 1:
        return None  # none takes it, or several and nothing decides which
    return office.operation(next(iter(ops))).verbs[0]


class RoundTripWork:
    """Built once per office (its rooms and the pattern over their names), read on every
    message."""

    def __init__(self, office: Office) -> None:
        self._office = office
        self._rooms = _rooms(office)
        names = "|".join(re.escape(n) for n in self._rooms)
        self._pattern = (
            re.compile(rf"{_CARRY}(?P<room>{names}){_BACK}", re.IGNORECASE) if names else None
        )

    def read(self, text: str, item_types: Callable[[str], set[str]]) -> str:
        """``text`` with "take X to <room> and bring it back" said as the work the room's
        facility does on X ("heat my lunch"); ``item_types`` gives the item types a phrase
        names (for "it", those the whole message names)."""
        if self._pattern is None or "back" not in text.lower():
            return text

        def as_work(m: re.Match[str]) -> str:
            thing = m.group("thing")
            # a pronoun's thing is the one the message named ("my lunch is cold, take it ...")
            pronoun = thing.lower() in _PRONOUNS
            types = item_types(text) if pronoun else item_types(thing)
            verb = _work_there(self._office, self._rooms[m.group("room").lower()], types)
            if verb is None:
                return m.group(0)
            return f"{verb} {thing}"

        return self._pattern.sub(as_work, text)
