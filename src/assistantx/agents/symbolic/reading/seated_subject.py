"""A colleague described by their place, as a need's subject: "the carver on bench 3 needs a
set square", "the new lad at desk 4 wants a stapler". A workstation is one colleague's place,
so the person said to be at it is that colleague: the phrase is said again as their name
("Eoin Byrne needs a set square"), and what follows reads as for a named colleague ("could
you bring him mine": him is Eoin, mine the speaker's, one hand-over). Without this the need
read as the speaker's own and a thing was fetched for the speaker as well.

The subject is a determiner, at most two describing words and a head noun, then "on", "at"
or "by" and the workstation's name, then a verb of need (english.yaml ``need_verbs``). Its head
noun may not end a name of the office's things or facilities ("the stapler on desk 3 needs ..."
is a thing, never rewritten); a word that only describes one may ("mason" of a "mason's
square": "the mason on banker 3 needs ..."; a colleague's name word after the determiner is
the English word), and the workstation must be the place of exactly one colleague (none, or
several: left as it is). Nothing here knows an office's words: they come from its file.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Iterable

from assistantx.core import english
from assistantx.core.office import Office

_NEEDS = english.words("need_verbs")
_DETERMINERS = ("the", "a", "an", "that", "this", "our", "your", "my")


class SeatedSubject:
    """The rewrite for one office: its workstations of one colleague each."""

    def __init__(self, office: Office, thing_heads: Collection[str]) -> None:
        """``thing_heads``: the last words of the office's things' and facilities' names."""
        self.thing_heads = thing_heads
        seated: dict[str, list[str]] = {}
        for p in office.people:
            seated.setdefault(p.location, []).append(p.name)
        self.names = {
            loc.name.lower(): seated[loc.id][0]
            for loc in office.workstations()
            if len(seated.get(loc.id, ())) == 1
        }
        self.pattern: re.Pattern[str] | None = None
        if self.names:
            places = "|".join(
                r"\s+".join(re.escape(w) for w in name.split())
                for name in sorted(self.names, key=len, reverse=True)
            )
            self.pattern = re.compile(
                r"\b(?P<det>" + "|".join(_DETERMINERS) + r")\s+"
                r"(?P<noun>(?:[^\W\d_]+\s+){0,2}[^\W\d_]+)\s+(?:on|at|by)\s+"
                r"(?P<place>" + places + r")\s+(?P<verb>" + "|".join(sorted(_NEEDS)) + r")\b",
                re.IGNORECASE,
            )

    @classmethod
    def of_names(cls, office: Office, thing_names: Iterable[str]) -> SeatedSubject:
        """The rewrite, with the heads of ``thing_names`` (the office's things' and
        facilities' names as said) as the nouns it leaves alone."""
        return cls(office, {n.split()[-1].lower() for n in thing_names if n.split()})

    def __call__(self, text: str) -> str:
        """``text`` with each such subject said as the colleague's name."""
        if self.pattern is None:
            return text

        def named(m: re.Match[str]) -> str:
            if m.group("noun").split()[-1].lower() in self.thing_heads:
                return m.group(0)  # "the stapler on desk 3 needs ...": a thing
            place = " ".join(m.group("place").lower().split())
            return f"{self.names[place]} {m.group('verb')}"

        return self.pattern.sub(named, text)
