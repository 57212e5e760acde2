"""A word that opens a report of a fault is its subject, not a command: "Drive in slot 4 on
R12 has died", "Van 3 is broken". The word may also be a verb of going out ("drive"), but
with a fault said of it a few words on ("has died", "is broken") the sentence states how a
thing is; it asks the robot to go nowhere (before, the whole message was declined as "an
errand outside the office" and the request after it was never read).

The fault is a form of "be" or "have" and one of the English states of a broken thing
(``conditions``, ``facility_failed``, ``facility_faults``), reached from the word before any
joining word ("drive to the shop and ..." keeps its verb) or pause, and only where no object
follows the word ("print my report, the printer is broken" asks for the printing)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english

_AUXILIARIES = frozenset(
    {"has", "have", "had", "is", "are", "was", "were", "s", "hes", "its", "just", "been", "now"}
)
# the first word of each state a fault is said with ("out" of "out of order")
_FAULTS = frozenset(
    e.split()[0]
    for key in ("conditions", "facility_failed", "facility_faults")
    for e in english.entries(key)
) - {"in", "working", "back", "fixed", "off", "busy", "not"}
# the words that end the subject's reach: a new clause, a relative one ("the page that's
# jammed" is the object's), or the ask after it
_JOINS = frozenset(
    {"and", "so", "then", "please", "pls", "but", "or", ",", "that", "which", "who", "because"}
    | {"if", "unless", "when", "while", "whilst", "as", "since", "till", "until", "once"}
    | {"before", "after"}
    # a subject of its own opens a new clause ("take Wang's stapler while she's out")
    | set(english.words("subject_pronouns"))
    | set(english.words("subject_contractions"))
)
# after a verb, its object opens ("print my report ..."): a subject's head is followed by a
# noun, a number or a preposition, never by these
_OBJECT_OPENERS = (
    frozenset(english.words("determiners"))
    | frozenset(english.words("object_pronouns"))
    | frozenset({"it", "me", "us", "you", "u"})
)
_REACH = 8  # "drive in slot 4 on r12 has died": the words from the subject to its "has"


def subject_of_fault(words: Sequence[str], n: int) -> bool:
    """Whether ``words[n]`` opens a subject a fault is said of ("drive ... has died")."""
    if n + 1 < len(words) and words[n + 1] in _OBJECT_OPENERS:
        return False  # "print my report the printer is broken": a verb and its object
    for k in range(n + 1, min(len(words), n + 1 + _REACH)):
        if words[k] in _JOINS:
            return False
        if words[k] in _AUXILIARIES:
            rest = [w for w in words[k + 1 : k + 4] if w not in _AUXILIARIES]
            return bool(rest) and rest[0] in _FAULTS
    return False
