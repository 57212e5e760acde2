"""A clipped or misspelt word after "my"/"our" that may mean several of the office's item
types names the one the speaker owns: "my batt's flat, can you get it charged" where the
speaker owns a camera battery and the office also keeps AA batteries (called "batts").

The lexicon reads a word it does not know by the nearest of the office's words ("batt" is one
letter from "batts") with no thought of whose it is; but "batt" also clips "battery" of the
camera battery. Said with "my", the thing is the speaker's own: of the types the word may
mean, the one the office file says the speaker owns wins. Where the speaker owns none or
several of them, a service the message asks for breaks the tie when it works on exactly one
of them ("charge" takes the camera battery). Anything else keeps the lexicon's reading.

The types a word may mean: the one the lexicon reads it as, each whose name has the word's
plural ("batts"), and each whose name has a word the said word clips (its first letters, at
least two letters short of it: "batt" of "battery", "mic" of "microphone"). Only a word that
is no word of the office as said: "my stapler" is read as it is.
"""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.head_noun_back import (
    names_something,
    opens_a_long_name,
)
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.task_schema import Evidence

_SPEAKERS = r"my|our"
_OWNED = re.compile(rf"\b(?:{_SPEAKERS})\s+(?P<word>[^\W\d_]+)\b", re.IGNORECASE)
_SHORTEST = 3  # "mic" of "microphone"
_SHORT_BY = 2  # "batt" of "battery"
_ITEMS = frozenset({"item"})


def owned_clipped(terms: Terms, text: str, requester: str) -> tuple[str, list[Evidence]]:
    """``text`` with each such word after "my"/"our" written as the name of the type meant."""
    found: list[Evidence] = []
    out: list[str] = []
    pos = 0
    for match in _OWNED.finditer(text):
        word = match.group("word").lower()
        if names_something(terms, word):
            continue  # "my stapler": the office's own word
        if _modifies_a_noun(text[match.end("word") :]):
            continue  # "my cert translation", "my customs declaration": the head comes after
        if opens_a_long_name(terms, text[match.start("word") :], _ITEMS):
            continue  # "my test records": the office's own name of several words, as said
        meant = _meant(terms, text, word, requester)
        if meant is None:
            continue
        name = terms.office.item_type(meant).name
        out += [text[pos : match.start("word")], name]
        pos = match.end("word")
        found.append(Evidence(words=match.group(0), meaning=f"the speaker's {name}"))
    return "".join(out) + text[pos:], found


_NEXT = re.compile(r"\s+(?P<next>[^\W\d_]+)")


def _modifies_a_noun(after: str) -> bool:
    """Whether the word is said before a noun of its own phrase ("cert *translation*"): a
    modifier of the thing named after it, never that thing clipped."""
    nxt = _NEXT.match(after)
    if nxt is None:
        return False
    word = nxt.group("next").lower()
    return language.is_noun(word) and not language.is_finite_verb(word)


def _meant(terms: Terms, text: str, word: str, requester: str) -> str | None:
    types = _types_of(terms, word)
    if len(types) < 2:
        return None  # one type or none: the lexicon's reading stands
    owned = {o.type for o in terms.office.person(requester).owns}
    mine = [t for t in types if t in owned]
    if len(mine) == 1:
        return mine[0]
    said = set(language.words(text.lower()))
    inputs = {
        op.input
        for op in terms.office.operations
        if op.input is not None and set(op.verbs) & _with_lemmas(said)
    }
    worked = [t for t in (mine or types) if t in inputs]
    return worked[0] if len(worked) == 1 else None


def _types_of(terms: Terms, word: str) -> list[str]:
    """The item types ``word`` may mean: the lexicon's reading, each type with a name's word
    that is the word's plural ("batts"), and each with a name's word it clips ("battery")."""
    mentions = terms.lex.read(word).mentions
    read = [m.ids[0] for m in mentions if m.kind == "item" and len(m.ids) == 1]
    plural = language.plural(word)
    fits = [
        t.id
        for t in terms.office.item_types
        if any(
            w == plural or _clips(word, w) for n in (t.name, *t.synonyms) for w in n.lower().split()
        )
    ]
    return list(dict.fromkeys([*read, *fits]))


def _clips(word: str, name_word: str) -> bool:
    """ "batt" of "battery", "mic" of "microphone": its first letters, two or more short."""
    return (
        len(word) >= _SHORTEST
        and name_word.isalpha()
        and name_word.startswith(word)
        and len(name_word) - len(word) >= _SHORT_BY
    )


def _with_lemmas(words: set[str]) -> set[str]:
    """The words and their verbs' lemmas ("charged" → "charge")."""
    return words | {lemma for w in words for lemma in language.verb_lemmas(w)}
