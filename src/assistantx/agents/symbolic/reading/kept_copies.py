"""A copy of a thing the office keeps for anyone is one of those things: "could I get a copy
of the staff handbook", "2 copies of the timetable pls", "a copy of thursday's catalogue"
(fix62b class 3). Where a cupboard or a counter keeps handbooks, timetables or catalogues,
"copy" only counts them, as "a copy of a book" does: one (or that many) is fetched. Read as
said, "copy" was the office's copying, declined where no machine copies ("nothing here
makes copies") or asked what to do with the thing where one does.

Only a thing some facility keeps as a supply for anyone, said right after "of" with at most
an article and words of which issue it is ("the", "today's", "thursday's", "this week's",
``kept_copy_editions``): never a paper of someone's ("a copy of my contract", "a copy of
Wang's document": a copy job where the office copies), a file, or stuff ("a copy of the
paper")."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english, language

_COUNTS = frozenset(english.words("number_words")) | {"a", "an", "one", "another"}
_EDITIONS = frozenset(english.words("kept_copy_editions"))
_COPY = re.compile(
    r"\b(?P<count>[A-Za-z]+|\d+)\s+(?:photo)?(?P<noun>copy|copies)\s+of\s+(?P<rest>[^,.;:!?]+)",
    re.IGNORECASE,
)
_POSSESSIVE = re.compile(r"(?:['’]s|s['’]?)$", re.IGNORECASE)


def _edition(word: str) -> bool:
    """ "the", "today's", "thursdays", "this", "week's": which issue of the thing is meant."""
    w = word.lower()
    if w in _EDITIONS:
        return True
    bare = _POSSESSIVE.sub("", w)
    return bare in _EDITIONS or language.is_weekday(bare)


def kept_copies(text: str, kept: Callable[[str], int]) -> str:
    """``text`` with "a copy of <a kept thing>" said as "a <thing>" ("2 copies of the
    timetable" -> "2 timetables"); ``kept`` gives how many words at a phrase's start name a
    thing the office keeps for anyone (0: none)."""

    def said(m: re.Match[str]) -> str:
        count = m.group("count")
        if count.lower() not in _COUNTS and not count.isdigit():
            return m.group(0)
        rest = m.group("rest")
        words = rest.split()
        n = 0
        while n < len(words) - 1 and _edition(words[n]):
            n += 1
        size = kept(" ".join(words[n:]))
        if not size:
            return m.group(0)
        name, after = " ".join(words[n : n + size]), " ".join(words[n + size :])
        one = count.lower() in ("a", "an", "one")
        if one:
            thing = f"{language.indefinite(name)} {name}"
        elif count.lower() == "another":
            thing = f"another {name}"
        else:
            thing = f"{count} {language.head_plural(name) or language.plural(name)}"
        return f"{thing} {after}".rstrip() + rest[len(rest.rstrip()) :]

    return _COPY.sub(said, text)
