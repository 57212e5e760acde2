"""A relative clause that says who has the thing: "I need the file Wang has", "bring me the
stapler Zhang's got", "the charger that Ray is holding", "the draft Zoltán has got, can you get
it to me?"; or a clause of its own right after it: "I need the file, Wang has it". English
names a thing by who has it as well as by a possessive; read without the clause, "the file"
was the requester's own (passed to herself) or anyone's stapler (a colleague not named asked
for theirs): wrong physical actions. The clause is said as the possessive it stands for
("Wang's file"), so the colleague is the owner or holder and is asked as for any owned thing.

Only a colleague's name (every word of it one of the office's names) and a verb of having
with nothing of its own after it ("has", "has got", "'s got", "is holding", "is using"; then
the clause's end, a stop, or a word that starts a new phrase): "the file Wang has signed" (a
perfect), "the file the team has" (no colleague) and "the file I have" (the requester's own,
read as before) are left as said."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import language

_WORD = r"[^\W\d_][\w-]*"
# the determiner that opens the thing's phrase ("*the* file Wang has")
_DETERMINERS = r"the|this|that"
# a verb of having after the name, "'s" spelled either way
_HAVING = (
    r"\s+has\s+got|['’]s\s+got|\s+has|\s+is\s+holding|['’]s\s+holding|\s+is\s+using"
    r"|['’]s\s+using|\s+is\s+keeping|['’]s\s+keeping|\s+got"
)
# what may follow the clause: its end, a stop, or a word that opens a phrase of its own
_AFTER = (
    r"(?=\s*(?:$|[,.;:!?)]|(?:and|so|then|now|please|pls|at|on|in|with|to|for|over|back"
    r"|right|already|today|can|could|would)\b))"
)
# a colleague's name, one word or two ("Wang", "Wang Fang"), never the verb after it
_WHO = rf"{_WORD}(?:\s+(?!(?:has|is|got)\b){_WORD})?"
_RELATIVE = re.compile(
    rf"\b(?:{_DETERMINERS})\s+(?P<thing>{_WORD}(?:\s+{_WORD}){{0,2}}?)\s+"
    rf"(?:(?:that|which)\s+)?(?P<who>{_WHO})(?:{_HAVING}){_AFTER}",
    re.IGNORECASE,
)
# "the file, Wang has it": a clause of its own right after the thing says who has it
_BESIDE = re.compile(
    rf"\b(?:{_DETERMINERS})\s+(?P<thing>{_WORD}(?:\s+{_WORD}){{0,2}}?)\s*[,;–—-]\s*"
    rf"(?P<who>{_WHO})(?:{_HAVING})\s+(?:it|them|that|one)\b",
    re.IGNORECASE,
)


def held_by_clauses(text: str, is_person_word: Callable[[str], bool]) -> str:
    """``text`` with each thing named by who has it said as that colleague's
    ("the file Wang has" → "Wang's file")."""

    def named(who: str, thing: str) -> bool:
        return (
            all(is_person_word(w) for w in who.split())
            and not any(is_person_word(w) for w in thing.split())
            and not _a_clause(thing)
        )

    def owned(m: re.Match[str]) -> str:
        who, thing = m.group("who"), m.group("thing")
        if not named(who, thing):
            return m.group(0)  # "the file the team has": no colleague
        return f"{who}'s {thing}"

    return _BESIDE.sub(owned, _RELATIVE.sub(owned, text))


def _a_clause(thing: str) -> bool:
    """Whether the words taken for the thing are a clause of their own: a past verb that is
    no noun after its subject ("the kettle died, Grace has it in hand": the fault, and who
    deals with it, not Grace's kettle)."""
    return any(language.is_past_verb(w) and not language.is_noun(w) for w in thing.split()[1:])
