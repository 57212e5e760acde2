"""A later step of the thing that names another of the office's services, said after a
request: "humidify my exhibit *before it goes on the ESDA*", "scan my form *so it's ready for
the lamination*", "print my poster *ahead of its laminating*", "copy it *before Sue laminates
it*". Such a clause says when or why the request is wanted, by what happens to the thing
afterwards (at a machine of the office, or by a service of the office), never a second request:
only the service asked before it is run. It is set aside before the pieces are judged, kept as
evidence, so neither the machine named nor the service's word picks or adds an operation.

Only a clause about the thing's own going ("before *it* goes", never "before *you* print it",
which orders two requests), or another's doing a service to it ("before Sue laminates it",
"before he signs them"), counts; only where its object names one of the office's facilities
or services ("before it goes to Acme" is the readings' ``in_later_event``); and only where a
request is left before it. "copy my document and then put it through the printer" asks both.
"""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS, split_words
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language
from assistantx.core.task_schema import Evidence

# the clause's object runs to a stop or a join ("..., and bring it back", "... then ...")
_OBJECT = r"(?P<obj>[^.,;:!?]*?)(?=\s*(?:$|[.,;:!?]|\b(?:and|then|please|pls|thanks)\b))"
_SUBJECTS = english.alternation("later_event_subjects")
_GOING = re.compile(
    rf"(?:,\s*)?\bbefore\s+(?:{_SUBJECTS})\s*(?:{english.alternation('later_event_goings')})"
    rf"\s+(?:{english.alternation('later_event_prepositions')})\s+{_OBJECT}",
    re.IGNORECASE,
)
_AHEAD = re.compile(
    r"(?:,\s*)?\b(?:so\s+(?:that\s+)?(?:it|they)(?:'s|’s|'re|’re|\s+is|\s+are|'ll\s+be|\s+will\s+be)"
    rf"\s+)?(?:{english.alternation('later_event_ahead')})\s+{_OBJECT}",
    re.IGNORECASE,
)
# "before Sue laminates it", "before he signs them": another's doing the service to the thing
_DOER = re.compile(
    r"(?:,\s*)?\bbefore\s+(?P<who>[^\W\d_]+)\s+(?P<verb>[^\W\d_]+)\s+(?:it|them)\b",
    re.IGNORECASE,
)
_THIRD_PERSONS = frozenset({"he", "she", "they"})
_OBJECT_REACH = 4  # the words of the object its machine or service is named in


def without_later_service(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` without its clauses of a later service on the thing, each kept as evidence."""
    found: list[Evidence] = []

    def names_service(obj: str) -> bool:
        words = [w for w in split_words(obj) if w not in DETERMINERS][:_OBJECT_REACH]
        if not words:
            return False
        if any(m.kind == "facility" for m in terms.lex.read(" ".join(words)).mentions):
            return True
        return any(_service_word(terms, w) for w in words)

    def drop(match: re.Match[str], meaning: str) -> str:
        left = (match.string[: match.start()] + match.string[match.end() :]).strip(" ,.!?")
        if not terms.lex.cue_words & set(split_words(left)) and not (
            terms.service_verbs & set(split_words(left))
        ):
            return match.group(0)  # nothing asked beside it: the clause is all there is
        found.append(Evidence(words=match.group(0).strip(" ,"), meaning=meaning))
        return ""

    def going(match: re.Match[str]) -> str:
        if not names_service(match.group("obj")):
            return match.group(0)  # "before it goes to Acme": a place outside, read later
        return drop(match, "when: before a later service")

    def ahead(match: re.Match[str]) -> str:
        if not names_service(match.group("obj")):
            return match.group(0)  # "ready for Friday", "ahead of the visit": said on
        return drop(match, "why: ready for a later service")

    def doer(match: re.Match[str]) -> str:
        who = match.group("who").lower()
        if who not in _THIRD_PERSONS and who not in terms.lex.name_words:
            return match.group(0)  # "before you print it": the order of two requests
        verb = match.group("verb").lower()
        if not verb.endswith("s") and who not in ("they",):
            return match.group(0)
        if not language.verb_lemmas(verb) & terms.service_lemmas:
            return match.group(0)  # "before he leaves it": no service of the office
        return drop(match, "when: before another's service")

    left = _DOER.sub(doer, _AHEAD.sub(ahead, _GOING.sub(going, text)))
    return (re.sub(r"\s{2,}", " ", left).strip(" ,"), found) if found else (text, [])


def _service_word(terms: Terms, word: str) -> bool:
    """Whether ``word`` names one of the office's services: a word of its verbs or name (not
    a word of an item's name), or a noun of its act ("lamination")."""
    if word in terms.lex.operation_nouns:
        return True
    if word in terms.lex.items:
        return False
    lemmas = language.verb_lemmas(word) | {word}
    return bool(lemmas & terms.service_lemmas) or (
        word in terms.service_verb_words and len(word) > 2
    )
