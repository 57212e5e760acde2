"""A colleague's "'s" for "is" before a coordinated need: "Gao's busy with the review and needs
a stapler, take her mine" is "Gao is busy ... and needs a stapler": Gao is the subject of
"and needs", so the need is Gao's, met by the request beside it. Read as a possessive
("Gao's <something> ... and needs") the clause lost its subject, the need became the
speaker's, and a second task brought the speaker a stapler (a wrong hand-over).

English tells the verb from the possessive by the word after "'s": a possessive names a
thing ("Gao's stapler", "Gao's old stapler": a noun, or an adjective before one); "is" is
followed by a state ("busy", "swamped"), a doing ("doing the slides", "working on ..."), or a
preposition ("with a client"). Only a clause with "and" and a third person's need verb after
it ("and needs", "and really wants") is rewritten; its subject must be the colleague, so no
other reading of the "'s" is left. "Gao's stapler is broken and I need one" (a thing, and the
speaker's own need) and "Gao's at her desk, take her my stapler" (no need joined) read as
before; where she is ("Gao's back", "Gao's off") is ``contracted_is``'s.
"""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS, split_words
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language
from assistantx.core.task_schema import Evidence

_PREPOSITIONS = english.words("prepositions_and_joins")
_WHEREABOUTS = english.words("contracted_whereabouts")  # contracted_is reads those
# a finite verb after the word: "Gao's back is sore" (the back is), never "Gao is back is"
_FINITE = frozenset({"is", "are", "was", "were", "has", "had", "needs", "wants", "s"})
# what may stand between "and" and the need's verb ("and really needs", "and now wants")
_ADVERBS = frozenset({"really", "also", "now", "still", "urgently", "badly", "just", "desperately"})
_NEEDS = frozenset({"needs", "wants"})
_CLAUSE_END = re.compile(r"[,.;:!?]")
_CONTRACTED = re.compile(r"\b(?P<subject>[^\W\d_]+)['’]s\s+(?P<state>[^\W\d_]+)\b")


def person_is(terms: Terms, text: str, requester: str) -> tuple[str, list[Evidence]]:
    """``text`` with a colleague's "'s" before a state, a doing or a preposition written as
    "is" where the clause goes on to "and needs"/"and wants"."""
    found: list[Evidence] = []

    def expand(match: re.Match[str]) -> str:
        subject = match.group("subject")
        end = _CLAUSE_END.search(text, match.end())
        clause = split_words(text[match.end("subject") : end.start() if end else len(text)])
        # clause: "s", the state, what follows
        if not _colleague(terms, subject, requester) or not _need_joined(clause[2:]):
            return match.group(0)
        state, after = clause[1], clause[2] if len(clause) > 2 else None
        if not (_says_is(terms, state, after) or _doing_before_need(state, clause[2:])):
            return match.group(0)
        found.append(Evidence(words=match.group(0), meaning=f"{subject} is {state}"))
        return f"{subject} is {match.group('state')}"

    return _CONTRACTED.sub(expand, text), found


def _colleague(terms: Terms, word: str, requester: str) -> bool:
    """Whether ``word`` names one colleague of the office other than the speaker."""
    ids = terms.lex.name_words.get(word.lower()) or terms.lex.people.get(word.lower()) or set()
    return len(ids) == 1 and requester not in ids


def _need_joined(words: list[str]) -> bool:
    """Whether the clause goes on to "and" and a third person's need ("and needs")."""
    for k, word in enumerate(words):
        if word != "and":
            continue
        rest = words[k + 1 :]
        while rest and rest[0] in _ADVERBS:
            rest = rest[1:]
        if rest[:1] and rest[0] in _NEEDS:
            return True
    return False


def _says_is(terms: Terms, state: str, after: str | None) -> bool:
    """Whether ``state`` (with ``after`` the word that follows it) is what "is" says of a
    person, not a thing the possessive names."""
    if state in terms.office_words or state in _WHEREABOUTS or state in DETERMINERS:
        return False
    if after is not None and (after in _FINITE or _noun_like(terms, after)):
        return False  # "Gao's old stapler", "Gao's back is sore": a thing of hers
    if state in _PREPOSITIONS:
        return True  # "Gao's with a client"
    read = language.lemmas(state)
    if language.is_present_participle(state):
        return True  # "Gao's doing the slides", "Gao's presenting"
    if "ADJ" in read:
        return True  # "Gao's busy"
    # "Gao's swamped", "Gao's tied up": a past participle
    return any(lemma != state for lemma in read.get("VERB", ()))


def _doing_before_need(state: str, rest: list[str]) -> bool:
    """ "Gao's doing slides and needs ...": a present participle and its bare object, then
    "and" with no finite verb between. A possessive's noun phrase ("Gao's charging cable")
    would be a subject with no verb of its own before the need, so the "'s" is the verb."""
    if not language.is_present_participle(state) or "and" not in rest:
        return False
    return not set(rest[: rest.index("and")]) & _FINITE


def _noun_like(terms: Terms, word: str) -> bool:
    """Whether ``word`` heads a noun after an adjective: one of the office's things, or a
    word the dictionary knows only as a noun ("laptop"), never one that also tells when
    ("today") or a determiner or preposition that opens what follows."""
    if word in DETERMINERS or word in _PREPOSITIONS or word == "and":
        return False
    if word in terms.office_words:
        return True
    read = language.lemmas(word)
    return "NOUN" in read and not read.keys() - {"NOUN", "VERB"} and "ADV" not in read
