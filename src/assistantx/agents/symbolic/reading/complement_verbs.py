"""An operation asked for by a verb with its complement ("write to tape", "burn to disc",
"commit to film"), read whole, and said with its object between the verb and the rest ("write
my data file to tape", "could you write the file to tape for me").

Such a verb's head alone ("write") is no word of the office's: the office declared the whole
phrase, and the whole asks for the work. Word by word, "to tape" reads as a destination
and the file as something passed on ("Who should I pass your file on to?"). So the phrase is
one of the office's declared phrases (``verb_phrases``), and where English puts the object
between its head and its complement, as it does with a short object ("write it to tape"), the
complement is moved back next to its head before the phrase is joined, as a particle is
("back my file up", ``verb_phrases.separated_particle``).

So is a phrase whose head asks alone for other work ("seal in plastic" of a laminator,
where "seal" alone is a colleague's seal): said with its complement, the whole phrase is what
the office declared ("seal my badge in plastic" is laminating it); "seal my document" keeps
its own reading. The words are the office's; the grammar (what a preposition and a function
word are) is English's.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_FUNCTION_WORDS = english.words("common")
# What joins a verb to its complement ("write *to* tape", "burn *onto* disc", "seal *in* ...").
_COMPLEMENT_PREPOSITIONS = frozenset({"to", "onto", "into", "in", "on"})
# The most words of an object between a verb and its complement ("write *my new data file*").
_OBJECT_WORDS = 4
# Words that end an object before any complement: another clause or phrase begins.
_OBJECT_ENDS = frozenset({"for", "at", "with", "from", "and", "then", "but", "or", "by"})


def complement_verb(phrase: str) -> bool:
    """Whether ``phrase`` is a verb, a preposition and a noun of its complement ("write to
    tape", "seal in plastic")."""
    words = phrase.split()
    if len(words) < 3 or words[1] not in _COMPLEMENT_PREPOSITIONS:
        return False
    if "VERB" not in language.lemmas(words[0]):
        return False
    return not any(w in _FUNCTION_WORDS for w in words[2:])


def tails_of(forms: Sequence[str]) -> dict[str, tuple[tuple[str, ...], ...]]:
    """Each head of the complement phrases' forms → the complements said after it
    ("writes" → ("to", "tape"))."""
    found: dict[str, set[tuple[str, ...]]] = {}
    for form in forms:
        head, *tail = form.split()
        found.setdefault(head, set()).add(tuple(tail))
    return {h: tuple(sorted(t, key=len, reverse=True)) for h, t in found.items()}


def separated_complement(
    tokens: Sequence[Token], n: int, tails: Mapping[str, tuple[tuple[str, ...], ...]]
) -> tuple[int, int] | None:
    """Where the complement of a declared phrase whose head is at ``n`` stands after an
    object of a few words ("write *my file* to tape"), as (start, length), or None: not
    across a pause or a sentence's end, nor where the head already has it after it."""
    said = tails.get(tokens[n].word, ())
    if not said or tokens[n].possessive:
        return None
    words = [t.word for t in tokens]
    for k in range(n + 1, min(len(tokens), n + 2 + _OBJECT_WORDS)):
        t = tokens[k]
        if t.opens or t.after_pause:
            return None
        for tail in said:
            if tuple(words[k : k + len(tail)]) == tail:
                return (k, len(tail)) if k > n + 1 else None
        if t.word in _OBJECT_ENDS:
            return None
    return None
