"""A room named by the first word of its name, said bare after "to": "can you take my wheel
down to wrapping" for the "Wrapping room", "pop it over to packing". People name the rooms
they work in that way, with no article; read as said, the word named no place, and the
thing was handed back to the speaker. The bare word is said again as the room's full name,
which the reader knows.

Only a name of two words whose second only says it is a room ("room", "office", "area",
"suite", "centre"), a first word of at least four letters that begins no other room's name
(the "Wrapping tables" in the Wrapping room leave it the room's) and is no word of the
office's things, people or services, nor a verb's plain form ("to post a letter" for a "Post
room"); only right after "to" or "into" ("in writing" names no room), with no article
between (a word with "the" before it, "for the meeting", is the English word, and so is a
word before a noun: "to wrapping paper"). Nothing here knows an office's words: they come
from its file.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Iterable

from assistantx.agents.symbolic.reading.clipped_names import ROOM_WORDS
from assistantx.core import language

_SHORTEST = 4


class BareRoom:
    """The rewrite for one office: its rooms said by their first word."""

    def __init__(self, names: Iterable[str], taken: Collection[str]) -> None:
        """``names``: the places' names as the office writes them; ``taken``: the words the
        office already uses for its things, people and services."""
        fronts: dict[str, list[str]] = {}
        for name in names:
            words = name.split()
            if len(words) == 2 and words[1].lower() in ROOM_WORDS:
                fronts.setdefault(words[0].lower(), []).append(name)
        self.rooms = {
            front: rooms[0]
            for front, rooms in fronts.items()
            if len(rooms) == 1
            and len(front) >= _SHORTEST
            and front.isalpha()
            and front not in taken
            and language.plural(front) not in taken
            and front not in language.verb_lemmas(front)  # "to post a letter": a verb
        }
        self.pattern: re.Pattern[str] | None = None
        if self.rooms:
            said = "|".join(re.escape(f) for f in sorted(self.rooms, key=len, reverse=True))
            self.pattern = re.compile(
                rf"\b(?P<to>to|into)\s+(?P<front>{said})\b(?!['’])(?P<next>\s+[^\W\d_]+)?",
                re.IGNORECASE,
            )

    def __call__(self, text: str) -> str:
        """``text`` with each such bare first word said as the room's full name."""
        if self.pattern is None:
            return text

        def room(m: re.Match[str]) -> str:
            after = (m.group("next") or "").strip()
            if after and language.is_noun(after.lower()):
                return m.group(0)  # "to wrapping paper": the English word before a noun
            return (
                f"{m.group('to')} the {self.rooms[m.group('front').lower()]}{m.group('next') or ''}"
            )

        return self.pattern.sub(room, text)
