"""An outsider named in a clause that says what someone else does or what the speaker needs,
not whom the item goes to: "take it to Penny, *she wants to show it to the guest*",
"photocopy my agreement pls, *need one for the client*".

The outsider rule (``outsider``) reads "to the guest" / "for the client" as the request's
recipient and asks whether to bring it to the requester instead. But a clause of its own (after
a comma or a sentence break, or "and"/"but") that opens with a subject other than "you" ("she
wants ...", "he's taking ...", "I need ...") or with the speaker's own need ("need one for
...") tells why: the guest is whom Penny shows it to, the client whom the speaker passes the
copy on to. The item then goes where the request says (Penny; the requester, who said they
need it), and nothing goes to the outsider. A clause that asks "you" anything ("I need you to
take it to the guest") is still a request to hand it over, and still asked about.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

_SUBJECTS = english.words("subject_pronouns") - {"you", "u", "ya", "it"}
_NEEDS = english.words("need_verbs")
_JOINS = english.words("clause_joins")
_ADDRESSED = frozenset({"you", "u", "ya", "yourself"})


def in_others_clause(
    tokens: Sequence[Token],
    breaks: Sequence[str],
    mentions: Sequence[Mention],
    at: int,
    *,
    later: bool = False,
) -> bool:
    """Whether the word at ``at`` stands in a clause of someone else's doing or the speaker's
    need (see the module's note), one that asks nothing of "you"; ``later``: the tokens are a
    piece of the message after its first, so their first word opens a clause too."""
    start = at
    while start > 0 and not breaks[start].strip() and tokens[start - 1].word not in _JOINS:
        start -= 1
    if start == 0 and not later:
        return False  # the request's own clause
    if any(t.word in _ADDRESSED for t in tokens[start:at]):
        return False
    first = tokens[start]
    person = any(m.kind == "person" and m.start == start for m in mentions)
    return first.word in _SUBJECTS or first.word in _NEEDS or person
