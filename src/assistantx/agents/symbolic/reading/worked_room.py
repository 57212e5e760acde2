"""A room named where work already spoken of is to be done: "my sample still hasn't been spun
down, could you get that done in the centrifuge room", "can you sort it in the badge office".
"Get it done at the centrifuge" asks for the centrifuge's service on the thing "it" stands
for, and the reader reads it so; said of the room the machine stands in, the room read as a
place the thing goes to, and who there should get it was asked. The room is said again as the
one machine in it that works on things ("... get that done at the centrifuge").

Only after a pro-form of work already named ("get it done", "have that done", "get them
sorted", "sort it") and "in"/"at"; only a room (never a desk) with exactly one facility whose
services work on a thing (an operation with an input): a room of two such machines, or of
none, is read as before. Carrying ("take it to the centrifuge room") is no such form and is
read as before. Nothing here knows an office's words: they come from its file.
"""

from __future__ import annotations

import re

from assistantx.core.office import Office

# "get it done in", "have that done at", "get them sorted in", "sort it at"
_ASKED = (
    r"\b(?P<head>(?:(?:get|have)\s+(?:it|that|this|them)\s+(?:done|sorted)"
    r"|sort\s+(?:it|that|this|them)(?:\s+out)?)\s+(?:in|at)\s+)"
)


def _head(name: str) -> str:
    """The last word of a name of several words ("booth" of "spray booth"); "" otherwise."""
    words = name.lower().split()
    return words[-1] if len(words) > 1 and words[-1].isalpha() else ""


class WorkedRoom:
    """The rewrite for one office: its rooms of one working machine, named as the machine."""

    def __init__(self, office: Office) -> None:
        machines: dict[str, list[str]] = {}
        for f in office.facilities:
            if any(office.operation(op).input is not None for op in f.operations):
                machines.setdefault(f.location, []).append(f.name)
        self._machine = {
            loc.name.lower(): machines[loc.id][0]
            for loc in office.locations
            if loc.kind != "workstation" and len(machines.get(loc.id, ())) == 1
        }
        # "get it done in the booth" of the "spray booth": the last word that the names of
        # one working machine end in (its room's too), when no other facility or place's does
        heads: dict[str, set[str]] = {}
        for f in office.facilities:
            for name in (f.name, *f.synonyms):
                heads.setdefault(_head(name), set()).add(f.name)
        for loc in office.locations:
            held = machines.get(loc.id, ())
            heads.setdefault(_head(loc.name), set()).add(held[0] if len(held) == 1 else loc.id)
        working = {n for names in machines.values() for n in names}
        for head, named in heads.items():
            only = next(iter(named))
            if head and len(named) == 1 and only in working:
                self._machine.setdefault(head, only)
        names = sorted(self._machine, key=len, reverse=True)
        self._pattern = (
            re.compile(
                _ASKED + r"(?:the\s+)?(?P<room>" + "|".join(map(re.escape, names)) + r")\b",
                re.IGNORECASE,
            )
            if names
            else None
        )

    def __call__(self, text: str) -> str:
        if self._pattern is None:
            return text

        def machine(m: re.Match[str]) -> str:
            return f"{m.group('head')}the {self._machine[m.group('room').lower()]}"

        return self._pattern.sub(machine, text)
