"""A clause after the first that opens with a present participle and no subject ("could I
borrow Will's calculator? doing a survey on the high street", "..., going to the bank
later"): the speaker's own doing, said as why, so it gets its "I'm" back before the pieces
are judged and is read as the statement it is. English asks with the plain form ("do a
survey", "go to the bank"), never with "-ing"; read as asked, the clause was an errand
outside the office and declined the inside request beside it. Only a clause after a stop or
a comma is restored (the message's first clause may be the whole request, as said); a clause
that ends asking ("printing it?") and one whose first word names something of the office
("meeting room 2", "packing tape") are left as said."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.core import language
from assistantx.core.task_schema import Evidence

# After a stop or a comma: a word in "-ing" and a word after it (a participle said alone,
# "..., thanks, cheering", is no doing with a place)
_CLAUSE = re.compile(r"([.!?;,]\s*|\n\s*)([A-Za-z]+ing)\b(?=\s+[A-Za-z0-9])")
# Mentions that make the "-ing" word part of a name: "meeting room 2", "packing tape"
_NAMING = frozenset({"item", "place", "facility", "person", "group"})


def _participle(word: str) -> bool:
    """A verb's "-ing" form that is not its plain form too ("bring", "sing")."""
    lemmas = language.verb_lemmas(word)
    return bool(lemmas) and word not in lemmas


def _clause_end(text: str, at: int) -> tuple[int, str]:
    """Where the clause going on at ``at`` ends, and the stop that ends it ("" at the end)."""
    end = re.search(r"[.!?;,\n]", text[at:])
    return (at + end.start(), end.group(0)) if end else (len(text), "")


def own_participle(text: str, read: Callable[[str], Lexed]) -> tuple[str, list[Evidence]]:
    """``text`` with "I'm" before each later clause that opens with a present participle
    (see the module's note), and what was restored."""
    found: list[Evidence] = []

    def restore(match: re.Match[str]) -> str:
        word = match.group(2).lower()
        if not _participle(word):
            return match.group(0)
        end, stop = _clause_end(match.string, match.start(2))
        if stop == "?":
            return match.group(0)  # "printing it?": asked
        clause = match.string[match.start(2) : end]
        if any(m.start == 0 and m.kind in _NAMING for m in read(clause).mentions):
            return match.group(0)  # "meeting room 2": a name of the office's, as said
        found.append(Evidence(words=clause.strip(), meaning="I'm (the speaker) doing"))
        return f"{match.group(1)}I'm {match.group(2)}"

    return _CLAUSE.sub(restore, text), found
