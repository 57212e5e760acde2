"""An ask said after a told state without a stop: "my phone is on 2% pls get me a charging
lead", "the printer is jammed can you bring me my file". Chat leaves out the stop between a
statement and the request after it; "please"/"pls" with a verb, or an asking modal with whom
it asks ("can u", "could you", "can someone"), opens a request of its own wherever it
stands. Read as one sentence, the statement's reading won and the request was lost ("Noted.
I did nothing."): a comma is put back before the ask, as ``consequence_boundary`` puts one
before "so".

Only after a told clause: one with a copula ("is", "are", "was") and that opens with no
asking word of its own ("is it free can you ...", "could you ... please bring ..." stay as
said), and only where the ask has words after it. A preface that ends in "but" needs no
copula ("I hope Mark won't mind but can I borrow his ruler"), and its ask may be the
speaker's own ("can I", "could we")."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.clause_marks import (
    WORD,
    clause_ends_between,
    with_commas_at,
)
from assistantx.core import english, language

_POLITE = english.words("polite")
_MODALS = frozenset({"can", "could", "would", "will"})
# whom the ask is put to: "can u ...", and anyone at all ("can someone bring me ...")
_ASKEES = frozenset({"you", "u", "ya"}) | (
    english.words("request_askees") & english.words("unnamed_doers")
)
_COPULAS = frozenset({"is", "are", "am", "was", "were"})
# A preface that ends in "but" ("I hope Mark won't mind but can I borrow his ruler", "sorry to
# bother you but could you ..."): told or not, it closes where the ask opens, and the ask may
# be the speaker's own ("can I", "could we")
_BUT = "but"
_ASKERS = frozenset({"i", "we"})
# what may open the clause before as an ask or a question of its own: then it is no told state
_ASKING = (
    english.words("request_modals")
    | english.words("question_auxiliaries")
    | english.words("wh_words")
    | _POLITE
)


def told_then_asked(text: str) -> str:
    """``text`` with a comma before each ask said right after a told state without one."""
    words = list(WORD.finditer(text))
    cuts: list[int] = []
    start = 0  # the first word of the current clause
    for n, m in enumerate(words):
        if n > start and clause_ends_between(text, words[n - 1], m):
            start = n
        if n - start < 3:
            continue
        clause = [w.group(0).lower() for w in words[start:n]]
        prefaced = clause[-1] == _BUT and _ask_at(words, n, _ASKEES | _ASKERS)
        if not (prefaced or _ask_at(words, n)):
            continue
        if clause[0] in _ASKING or not (prefaced or set(clause[1:]) & _COPULAS):
            continue
        cuts.append(words[n - 1].end())
        start = n
    return with_commas_at(text, cuts)


def _ask_at(words: list[re.Match[str]], n: int, askees: frozenset[str] = _ASKEES) -> bool:
    """Whether an ask opens at word ``n``: "pls get ...", "can u bring ...", words after it."""
    said = [w.group(0).lower() for w in words[n : n + 3]]
    if len(said) < 2:
        return False
    if said[0] in _POLITE:
        return said[1] in language.verb_lemmas(said[1])  # "pls get", never "pls thanks"
    return said[0] in _MODALS and said[1] in askees and len(said) == 3
