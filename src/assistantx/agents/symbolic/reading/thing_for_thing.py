"""A thing of the office that needs another, and the other asked for by a stand-in: "the DI
needs a fresh 9V battery, could you fetch me one?", "the printer needs paper, can you grab
some". The thing that needs is the subject, what it is for: nobody asks for it. "one" and
"some" stand for what it needs, so only that is wanted. The reader had fetched both, the DI
box as well as the battery. The thing needed is said, with the thing it is for,
in the ask, in the stand-in's place ("could you fetch me a fresh 9V battery for the DI
box?"), which the reader reads as the battery alone, for whoever the ask names.

Only where the subject is one of the office's things (a colleague's need, "Wang needs a
stapler, bring her one", is read by the rules for people), what is needed is another of its
things, and the ask after it names no thing of its own but a stand-in ("one", "some")."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

_STANDINS = english.words("standin_quantities")
_OPENERS = english.words("thing_openers")
_SUPPLY_OPENERS = english.words("supply_openers")
_NEED = r"needs|need|wants|could\s+do\s+with|could\s+use"
# the stand-in said as one word ("one", "some"), the first in the ask
_CLAUSE = re.compile(
    rf"(?P<head>(?:^|(?<=[.!?;]\s))[^,;.!?\-]*?)\s+(?:{_NEED})\s+(?P<want>[^,;.!?]+?)"
    rf"(?P<sep>\s*[,;.\-]|\s+(?:so|and)\b)(?P<rest>[^.!?;]*)",
    re.IGNORECASE,
)
_ONE_WORD = frozenset(w for w in english.entries("standin_quantities") if " " not in w)
_MOST_WORDS = 4  # the longest name of a thing read on either side of "needs"


class ThingForThing:
    """The rewrite, with the office's reading of a phrase: the item types it names, and
    whether it is one of the office's items and nothing else."""

    def __init__(
        self,
        item_types: Callable[[str], set[str]],
        names_item: Callable[[str], bool],
    ) -> None:
        self.item_types = item_types
        self.names_item = names_item

    def __call__(self, text: str) -> str:
        return _CLAUSE.sub(self._said, text)

    def _said(self, m: re.Match[str]) -> str:
        head = m.group("head").split()
        opener = head[0] if head and head[0].lower() in _OPENERS else ""
        thing = " ".join(head[1:] if opener else head)
        want = m.group("want").split()
        k = 0
        while k < len(want) and want[k].lower() in _SUPPLY_OPENERS:
            k += 1
        needed = " ".join(want[k:])
        if not (0 < len(head) <= _MOST_WORDS and 0 < len(want) - k <= _MOST_WORDS):
            return m.group(0)
        if not (self.names_item(thing) and self.names_item(needed)):
            return m.group(0)  # a person's need, or no thing of the office's
        thing_types, needed_types = self.item_types(thing), self.item_types(needed)
        if not thing_types or not needed_types or thing_types & needed_types:
            return m.group(0)
        rest = m.group("rest")
        said = {w.lower() for w in re.findall(r"[^\W_]+", rest)}
        if not said & _STANDINS or self.item_types(rest):
            return m.group(0)  # "..., bring me the stapler too": its own thing, as said
        standin = re.search(
            rf"\b(?:{'|'.join(sorted(_ONE_WORD, key=len, reverse=True))})\b", rest, re.I
        )
        if standin is None:
            return m.group(0)  # "a couple": left as said
        whose = (opener or "the").lower()
        wanted = f"{m.group('want')} for {whose} {thing}"
        asked = rest[: standin.start()] + wanted + rest[standin.end() :]
        return asked.strip()
