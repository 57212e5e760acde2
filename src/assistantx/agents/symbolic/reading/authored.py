"""A thing named by a colleague's making of it: "the slides Zhang did", "the report Wang
wrote", "the contract Zhou drew up", "the spreadsheet that Sun made last week".

A relative clause "<colleague> <verb of making, past> (<particle>)" after a noun of the
office's files or papers says whose the thing is, as a possessive would: "the slides Zhang
did" is "Zhang's slides", asked of Zhang as any colleague's file is. Read as it stood, "the"
made it nobody's, so the requester's own was taken (or whose was asked). The clause is no
request: its verb is past and its subject a colleague, and it ends there (a stop, the message's
end, a word that opens a phrase of its own, or when: "last week").

Left as said: the speaker's own making ("the slides I did": ``own_made`` reads it as "my"),
a verb that is no making ("the report Wang wants"), a making verb with someone as its object
("the report Wang made me sign"), a thing that is no file or paper of a person's ("the coffee
Wang made"), and sending ("the file Wang sent": ``sent_file``). The verbs are english.yaml's
``authoring_verbs``."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.agents.symbolic.reading.sent_file import relative_clauses
from assistantx.core import english

_VERBS = "|".join(sorted(english.words("authoring_verbs"), key=len, reverse=True))
_PARTICLES = "|".join(sorted(english.words("own_making_particles")))
# when it was made: said after the clause and dropped with it
_WHEN = (
    r"(?:\s+(?:earlier|yesterday|today|just\s+now|this\s+morning|this\s+week|last\s+night"
    r"|last\s+week|last\s+month|the\s+other\s+day))?"
)
# "the slides Zhang did": the relative clause of a making verb (``sent_file``'s shape)
_CLAUSES = relative_clauses(rf"(?:{_VERBS})(?:\s+(?:{_PARTICLES}))?{_WHEN}")


def authored_things(
    text: str, is_person_word: Callable[[str], bool], authored: Callable[[str], bool]
) -> str:
    """``text`` with each file or paper named by the colleague who made it said as that
    colleague's ("the slides Zhang did" → "Zhang's slides"). ``authored``: whether the
    thing's words name one of the office's files or personal papers and nothing else."""

    def owned(m: re.Match[str]) -> str:
        who, thing = m.group("who"), m.group("thing")
        if any(is_person_word(w) for w in thing.split()):
            return m.group(0)
        if not all(is_person_word(w) for w in who.split()) or not authored(thing):
            return m.group(0)  # "the slides I did", "the report the client wrote"
        return f"{who}'s {thing}"

    for clause in _CLAUSES:
        text = clause.sub(owned, text)
    return text
