"""An owner described before the possessive is a role, not a colleague: "print the site
engineer's report for me", "the Hartley loss adjuster's report", "the Acme account
manager's invoice". English describes a kind of person with words between the determiner
and the noun (a firm, a place, a field of work: "the *site* engineer", "the *Acme account*
manager"); a colleague is named, not described so. The owner is then someone outside the
office, like "the chiropodist's invoice" (``outsider_owner``), and the paper is the
speaker's in hand, even where the noun is one the office's people are called by ("manager"
of "Manager Mao"): "the Acme account manager" is Acme's.

A description is nouns and capitalised names only: an adjective ("the new manager's") may
still describe a colleague, and a word of grammar ends it ("drop my folder on ivy's desk":
Ivy, a colleague). None of its words may be a word of the office's own names for its
people, nor one that places the person in this office ("the office manager's", "the team
leader's"): those still name a colleague."""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import TYPE_CHECKING

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

if TYPE_CHECKING:  # the lexicon reads its mentions through this module
    from assistantx.agents.symbolic.reading.lexicon import Mention

_DETERMINERS = frozenset({"the", "this", "that", "a", "an", "my", "our", "your"})
_COMMON = english.words("common")  # "on", "to", "and": grammar, never a description
_MOST_DESCRIBING = 3  # "the Hartley loss adjuster's": two words, "the Acme UK site ..."
# words that place the described person in the speaker's own office: still a colleague
_OWN_PLACE = frozenset({"office", "team", "department", "floor"})


def described_determiner(tokens: Sequence[Token], start: int, office_words: frozenset[str]) -> str:
    """The word that opens the description of the possessive at ``start``: its determiner
    ("the" of "the site engineer's"), or the command's verb before a description a name opens
    ("print" of "print Hartley loss adjuster's report": the determiner dropped, as in a
    note); "" where no description of a kind of person opens there."""
    said, k = 0, start - 1
    while k >= 0:
        t = tokens[k]
        if t.word in _DETERMINERS:
            return t.word if said else ""
        if said and tokens[k + 1].text[:1].isupper() and _plain_verb(t):
            return t.word  # a name opens the description, right after the command's verb
        if said == _MOST_DESCRIBING or not _describing(t, office_words):
            return ""  # "drop my folder on ivy's desk": "on" describes nobody
        said += 1
        if t.opens or t.after_pause:
            return ""
        k -= 1
    return ""


def _plain_verb(t: Token) -> bool:
    """ "print", "send": a verb's plain form in lower case, as a command opens with."""
    return t.text[:1].islower() and not t.possessive and t.word in language.verb_lemmas(t.word)


def _describing(t: Token, office_words: frozenset[str]) -> bool:
    """Whether ``t`` may describe a kind of person: a noun ("site", "loss", "county") or a
    capitalised name ("Acme"); no word of English's grammar, no possessive ("Wang's
    engineer's"), no word of the office's people, none placing the person in this office."""
    if t.possessive or not t.word.isalpha() or t.word in _COMMON:
        return False
    if t.word in office_words or t.word in _OWN_PLACE:
        return False
    # a word the dictionary does not know ("county") is a noun of the name, as elsewhere
    return t.text[:1].isupper() or language.is_noun(t.word) or not language.lemmas(t.word)


def described_role(tokens: Sequence[Token], m: Mention, office_words: frozenset[str]) -> bool:
    """Whether the possessive mention ``m`` (one word, a noun, in lower or title case) is a
    role by its description ("the site engineer's", "the Loss Adjuster's"), no colleague."""
    if not m.possessive or m.end - m.start != 1:
        return False
    # in title case too ("the Hartley Loss Adjuster's"), where the word is no one's name here;
    # a colleague's name in capitals ("a pen. Lee's is fine") is the colleague
    if m.text[:1].isupper() and (m.kind != "word" or tokens[m.start].opens):
        return False
    word = tokens[m.start].word
    return language.is_noun(word) and bool(described_determiner(tokens, m.start, office_words))


def as_described_roles(
    tokens: Sequence[Token], mentions: Sequence[Mention], office_words: frozenset[str]
) -> list[Mention]:
    """``mentions`` with a colleague's title word described as a role read as a plain word
    ("the Acme account *manager's*": no Manager Mao)."""
    return [
        dataclasses.replace(m, kind="word", ids=(tokens[m.start].word,))
        if m.kind == "person" and described_role(tokens, m, office_words - {tokens[m.start].word})
        else m
        for m in mentions
    ]
