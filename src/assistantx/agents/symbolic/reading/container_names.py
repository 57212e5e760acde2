"""A colleague called by a word for a waste container ("Skip Larsen", called "Skip"; a "Bin").

"to" both names whom a thing goes to ("send my file to Skip") and puts it into a container
("chuck it to the skip"), so after it the name word alone does not say which is meant. English
does: a container is a countable noun and takes an article ("in the skip", "into a bin"),
while a name takes none and is written with a capital. So after "to", with no article:

- written with a capital mid-sentence ("send my file to Skip"): the colleague, as any name;
- in lower case ("give my report to skip"): either, and the two lead to different physical
  acts (a hand-over, or something the assistant declines), so it is asked: "Do you mean Skip
  Larsen, or the skip?";
- after an article ("in the skip", "to the bin"): the container, as before (the name reading
  already makes it the word).

Only an office with someone so called has the doubt: elsewhere "skip" is never a name."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

# the one-word waste containers ("skip", "bin", "trash"): a phrase ("waste bin") is no name
CONTAINER_WORDS = frozenset(e for e in english.entries("waste_containers") if " " not in e)
# the prepositions that both put a thing into a place and name whom it goes to: "to"
RECIPIENT_INTO = english.words("to_facility_prepositions") & english.words("person_before")


def after_recipient_into(tokens: Sequence[Token], i: int) -> bool:
    """Whether the word at ``i`` follows, in its sentence, a preposition that may name either
    a recipient or where a thing is put ("to"), with no article between."""
    return i > 0 and not tokens[i].opens and tokens[i - 1].word in RECIPIENT_INTO


def doubted_container(tokens: Sequence[Token], i: int) -> bool:
    """Whether the name word at ``i`` may as well be the waste container it is spelled as: a
    container word, in lower case, not possessive, right after "to" ("give my report to
    skip"). The caller has already read it as a person by its syntax."""
    t = tokens[i]
    if t.word not in CONTAINER_WORDS or t.possessive or t.corrected:
        return False
    return t.text[:1].islower() and after_recipient_into(tokens, i)


def container_phrase(tokens: Sequence[Token], i: int) -> str:
    """The container as the question names it: "the skip"."""
    return f"the {tokens[i].word}"
