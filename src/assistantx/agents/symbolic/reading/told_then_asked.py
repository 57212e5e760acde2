"""An ask said after a told state without a stop: "my phone is on 2% pls get me a charging
lead", "the printer is jammed can you bring me my file". Chat leaves out the stop between a
statement and the request after it; "please"/"pls" with a verb, or an asking modal with whom
it asks ("can u", "could you", "can someone"), opens a request of its own wherever it
stands. Read as one sentence, the statement's reading won and the request was lost ("Noted.
I did nothing."): a comma is put back before the ask, as ``consequence_boundary`` puts one
before "so".

An ask put as a question to anyone ("anyone got a cable i can borrow", "anybody have some",
"any chance of a coffee", the language data's ``run_on_asks``) opens one too: "my phone's on
3% anyone got a cable i can borrow" was one told piece ("Noted. I did nothing.").

Only after a told clause: one with a copula ("is", "are", "was", "my phone's") or a past verb
after its first word ("my stapler broke can u bring me Wang's"), that opens with no asking word
of its own ("is it free can you ...", "could you ... please bring ..." stay as said), and only
where the ask has words after it. An ask right after a verb of reporting ("Wang said can you
bring him his stapler") is the words reported, left as said. A preface that ends in "but" needs
no copula ("I hope Mark won't mind but can I borrow his ruler"), and its ask may be the
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
# "anyone got ...", "any chance ...": an ask to anyone, as word sequences
_RUN_ON_ASKS = frozenset(tuple(e.split()) for e in english.entries("run_on_asks"))
_REPORTING = english.words("reporting_verbs")
_OPENERS = english.words("thing_openers")


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
        if clause[0] in _ASKING or clause[-1] in _REPORTING:
            continue
        if not (
            prefaced
            or set(clause[1:]) & _COPULAS
            or _contracted_copula(clause)
            or _finite_verb(clause)
        ):
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
    if any(
        len(said) > len(ask) and tuple(said[: len(ask)]) == ask
        for ask in _RUN_ON_ASKS
        if askees is _ASKEES
    ):
        return True  # "anyone got a cable ...": words after the ask
    return said[0] in _MODALS and said[1] in askees and len(said) == 3


def _contracted_copula(clause: list[str]) -> bool:
    """ "my phone's flat", "the printer's out": a thing's "is" run into its noun, said after
    the words that open a thing's phrase (never "Wang's stapler", a possessive)."""
    return clause[0] in _OPENERS and clause[1].endswith(("'s", "’s"))


def _finite_verb(clause: list[str]) -> bool:
    """Whether a told clause holds a past verb after its first word ("my stapler broke"), and
    opens with none of its own (an imperative: "print me a sheet ..."). A past form only: a
    plural noun reads as a verb's "-s" form ("slides", "shears")."""
    if language.verb_lemmas(clause[0]) and clause[0] in language.verb_lemmas(clause[0]):
        return False
    return any(_past_form(w) for w in clause[1:] if w not in _ASKING)


def _past_form(word: str) -> bool:
    return any(
        word in language.verb_inflections(lemma).get("VBD", ())
        for lemma in language.verb_lemmas(word)
    )
