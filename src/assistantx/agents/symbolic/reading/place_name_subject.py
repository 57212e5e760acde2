"""A facility or place whose name opens with a service's verb, said first as the clause's
subject: "drying room's absolutely roasting again", "binding room is freezing". The first
word ("drying", "binding") is a word of the name, not a command to dry or bind: the whole
name said first is the subject, so the clause is no imperative. Only a name of two words or
more counts: a one-word name ("fax" for the fax machine) is the verb itself ("fax my
contract")."""

from __future__ import annotations

from collections.abc import Iterable, Sequence


def opens_with_place_name(words: Sequence[str], names: Iterable[str]) -> bool:
    """Whether ``words`` open with a whole name of several words from ``names`` (the
    lexicon's facility and place phrases) and go on past it."""
    for name in names:
        said = name.split()
        if len(said) < 2 or len(words) <= len(said):
            continue
        head, last = list(words[: len(said) - 1]), words[len(said) - 1]
        # the pieces' words keep a possessive "s" on the last word ("drying rooms" for
        # "drying room's", the "'s" of "is")
        if head == said[:-1] and last in (said[-1], f"{said[-1]}s"):
            return True
    return False
