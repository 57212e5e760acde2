"""The speaker's own one: "Wang wants a book, can you take him *my spare one*", "bring her my
other one", "my old one will do".

"one" stands for the thing named before it, as in "a spare one"; "my" before it says whose,
as "mine" does (``rewrites.dangling_possessives``). Read as "a book", the "my" was lost and
anyone's book was taken to Wang (a colleague's, where the requester offered their own). The
describing words between ("spare", "other", "old", "second") choose nothing the office keeps
a record of, so "my spare one" is the requester's own thing of that kind, "my book", read
from there on as "my book" is (one the office does not list as theirs is asked of them as
their "my book" would be)."""

from __future__ import annotations

import re
from collections.abc import Callable, Container

from assistantx.core import language
from assistantx.core.task_schema import Evidence

# words that set one of a person's things apart from another without naming a new thing;
# the tagger takes some of them for other parts of speech ("spare" a verb, "other" a
# determiner), so they are listed, and any other adjective counts as well
_SETTING_APART = frozenset(
    {"spare", "other", "old", "second", "extra", "backup", "usual", "own", "older", "new"}
)

# "my one", "my spare one", "my old spare one": up to two words between "my" and "one"
_MY_ONE = re.compile(
    r"\b(?P<whose>my|our)\s+(?P<words>(?:[^\W\d_]+\s+){0,2}?)one\b(?!\s+of\b)",
    re.IGNORECASE,
)


def own_ones(
    text: str, items: Container[str], thing_before: Callable[[str], str | None]
) -> tuple[str, list[Evidence]]:
    """``text`` with each "my <describing words> one" read as "my <thing>", the thing named
    last before it (``thing_before`` of the text before it); words that name a thing of
    ``items`` ("my paper one") or no thing named before leave it as it was."""
    evidence: list[Evidence] = []

    def read(match: re.Match[str]) -> str:
        words = match.group("words").lower().split()
        if not all(_sets_apart(w, items) for w in words):
            return match.group(0)
        thing = thing_before(text[: match.start()])
        if thing is None:
            return match.group(0)
        said = f"{match.group('whose')} {thing}"
        evidence.append(Evidence(words=match.group(0), meaning=said))
        return said

    return _MY_ONE.sub(read, text), evidence


def _sets_apart(word: str, items: Container[str]) -> bool:
    if word in items:
        return False
    return word in _SETTING_APART or "ADJ" in language.lemmas(word)
