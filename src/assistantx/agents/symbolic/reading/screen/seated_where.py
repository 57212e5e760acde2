"""Where a person is, said after their name: "Sue on reception needs a highlighter", "Wang at
the print room needs paper", "Mark by the kitchen could use a ruler".

A preposition of place and one of the office's places or facilities right after a name that
opens a sentence, with the sentence's verb next, says where that person is, as a way of
pointing them out; it names no second thing, no source and no destination. Left in, it cut
the subject from its verb: "needs" had no subject, so the person was read as the owner of the
thing ("Sue ... highlighter": Sue's own, for the requester), a wrong delivery. The office
knows where everyone sits, so the phrase is taken out before the message is read. A name
that does not open the sentence ("bring Wang at desk 6 a pen"), a possessive ("Sue's
highlighter from reception") or a place with no verb after it is left as written.

The same holds for a recipient found at one of the office's facilities: "print it and give it
to Wang at the coffee machine, he needs it" points Wang out; read as a thing, the facility's
product (a coffee) was made for Wang and the printout went to the requester. A facility said
right after "to/for <name>", up to the clause's end, is taken out too; a room ("to Wang in the
meeting room") is where the thing goes, and stays."""

from __future__ import annotations

import functools
import re

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.office import Office
from assistantx.core.task_schema import Evidence

# prepositions that place a person ("on reception", "at the print room", "by the kitchen")
_PLACING = ("on", "at", "in", "by", "near")
# modals that open the verb after the subject ("could use", "would like")
_MODALS = frozenset({"can", "could", "would", "will", "might", "may", "should", "must"})


@functools.cache
def _places(office: Office) -> re.Pattern[str]:
    names = {loc.name for loc in office.locations}
    names |= {n for f in office.facilities for n in (f.name, *f.synonyms)}
    spelled = sorted((re.escape(n) for n in names if n.strip()), key=len, reverse=True)
    return re.compile(
        rf"\s+(?:{'|'.join(_PLACING)})\s+(?:the\s+)?(?:{'|'.join(spelled)})\b(?=\s+(\w+))",
        re.IGNORECASE,
    )


# the words after which a name is the thing's recipient ("give it *to* Wang at ...")
_RECEIVING = frozenset({"to", "for"})
# what may follow a recipient's facility phrase: the clause ends there
_CLAUSE_ENDS = frozenset(
    {"and", "then", "he", "she", "they", "as", "so", "because", "please", "pls"}
)


@functools.cache
def _facilities(office: Office) -> re.Pattern[str]:
    names = {n for f in office.facilities for n in (f.name, *f.synonyms)}
    spelled = sorted((re.escape(n) for n in names if n.strip()), key=len, reverse=True)
    return re.compile(
        rf"\s+(?:{'|'.join(_PLACING)})\s+(?:the\s+)?(?:{'|'.join(spelled)})\b(?=\s*([,.;!?]|\w+|$))",
        re.IGNORECASE,
    )


def _verb_next(word: str) -> bool:
    w = word.lower()
    return w in _MODALS or language.is_finite_verb(w)


def without_seating(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with each "<place phrase>" after a sentence-opening name taken out."""
    found: list[Evidence] = []
    out = text
    for match in reversed(list(_places(terms.office).finditer(text))):
        if not _verb_next(match.group(1)):
            continue
        lexed = terms.lex.read(text[: match.start()])
        if not lexed.mentions or not lexed.tokens:
            continue
        last = lexed.mentions[-1]
        if last.kind != "person" or last.possessive or last.end != len(lexed.tokens):
            continue
        if not lexed.tokens[last.start].opens and not lexed.tokens[last.start].after_pause:
            continue
        found.append(Evidence(words=match.group(0).strip(), meaning="where they are"))
        out = out[: match.start()] + out[match.end() :]
    if not terms.office.facilities:
        return out, found
    for match in reversed(list(_facilities(terms.office).finditer(out))):
        after = match.group(1).lower()
        if after.isalnum() and after not in _CLAUSE_ENDS:
            continue  # "to Wang at the printer room": more of the place, or a clause goes on
        lexed = terms.lex.read(out[: match.start()])
        if len(lexed.mentions) < 1 or not lexed.tokens:
            continue
        last = lexed.mentions[-1]
        if last.kind != "person" or last.possessive or last.end != len(lexed.tokens):
            continue
        if last.start == 0 or lexed.tokens[last.start - 1].word not in _RECEIVING:
            continue
        found.append(Evidence(words=match.group(0).strip(), meaning="where they are"))
        out = out[: match.start()] + out[match.end() :]
    return out, found
