"""A reason told right after a causative request without a stop: "can u get my swab tested
the reading looked off on my kit". "get/have <the thing> <participle>" asks for work on that
thing ("tested"), and a clause that follows with a subject of its own and its verb ("the
reading looked ...", "my results were ...") explains why; read as one clause, a thing named
in the reason ("my kit") took the request over and was asked about. A comma is put back after
the participle, as ``told_then_asked`` puts one before an ask.

Only where the participle ends a causative on a definite thing (a determiner after
"get"/"have", a name of three words at most) and the words after it open a noun phrase with a
determiner whose next word or the one after is a finite verb: "get my file printed the same
way" and "have the form signed the day it is due" stay as said."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.clause_marks import (
    WORD,
    clause_ends_between,
    with_commas_at,
)
from assistantx.core import english, language

_CAUSING = frozenset({"get", "have", "got", "had", "getting", "having"})
_DETERMINERS = frozenset({"my", "our", "the", "this", "that", "these", "those", "his", "her"})
_OBJECTS = _DETERMINERS | {"it", "them"}
_STATES = english.words("state_verbs")
_PRONOUNS = english.words("subject_pronouns")
_NAME_WORDS = 3  # the words of the thing's name between its determiner and the participle
_SUBJECT_WORDS = 2  # the words of the reason's subject after its determiner


def caused_then_told(text: str) -> str:
    """``text`` with a comma after each causative's participle that a told reason follows
    without one."""
    words = list(WORD.finditer(text))
    said = [w.group(0).lower() for w in words]
    cuts: list[int] = []
    for n, word in enumerate(said):
        if word not in _CAUSING or n + 2 >= len(said) or said[n + 1] not in _OBJECTS:
            continue
        first = n + 2 if said[n + 1] in ("it", "them") else n + 3
        for p in range(first, min(first + _NAME_WORDS, len(said))):
            if _joined(text, words, n, p):
                break
            if language.is_past_participle(said[p]) and _reason_at(text, words, said, p + 1):
                cuts.append(words[p].end())
                break
    return with_commas_at(text, cuts)


def _joined(text: str, words: list[re.Match[str]], n: int, p: int) -> bool:
    """Whether a clause ends between word ``n`` and word ``p``."""
    return clause_ends_between(text, words[n], words[p])


def _reason_at(text: str, words: list[re.Match[str]], said: list[str], k: int) -> bool:
    """Whether a told clause opens at word ``k`` with no stop before it: a determiner, a
    subject of a word or two, and a finite verb ("the reading looked ...")."""
    if k >= len(said) or said[k] not in _DETERMINERS or _joined(text, words, k - 1, k):
        return False
    for v in range(k + 2, min(k + 2 + _SUBJECT_WORDS, len(said))):
        if said[v - 1] in _PRONOUNS:
            return False  # "the day *it* is due": a clause inside the phrase, no subject
        if said[v] in _STATES or language.is_finite_verb(said[v]):
            return not _joined(text, words, k, v)
    return False
