"""The words of a person's full name that may call them by themselves.

A name of three words or more has parts in its middle that nobody is called by alone: the
Vietnamese middle name ("Nguyễn *Thị* Mai", "Trần *Văn* An") and the particles of Spanish,
Dutch, Welsh and Arabic names ("María *de la* Cruz", "Jan *van* Dijk", "Rhys *ap* Dafydd",
"Omar *bin* Said"). Read as names, they make ordinary words into people ("*this* job card"
as Thị's, "a *van*", "the *bins*"). Only the first and the last word of a full name call its
bearer alone; a middle word does so only where the office declares it as an alias. The
surname with its particles ("de la Cruz", "van Dijk") still names the person as a phrase.
"""

from __future__ import annotations

from assistantx.core import english
from assistantx.core.office import Person

# "Ms Quinn Ashby": a title written into the full name is no part of the name proper
_TITLES = english.words("titles") - {"a", "an", "the", "our"}


def _proper(person: Person) -> list[str]:
    words = person.name.split()
    n = 0
    while n < len(words) - 1 and words[n].casefold().rstrip(".") in _TITLES:
        n += 1
    return words[n:]


def calling_words(person: Person) -> tuple[str, ...]:
    """The words of ``person``'s full name that name them alone, as written: the first and
    the last, and any middle word that is also one of their one-word aliases."""
    words = _proper(person)
    if len(words) <= 2:
        return tuple(person.name.split())
    aliases = {a.casefold() for a in person.aliases if len(a.split()) == 1}
    middle = [w for w in words[1:-1] if w.casefold() in aliases]
    return (words[0], *middle, words[-1])


def surname_phrases(person: Person) -> tuple[str, ...]:
    """The runs of a full name of three words or more that end with its last word and hold
    more than one word ("de la Cruz", "la Cruz", "van Dijk"): a surname with its particles,
    which names its bearer as a whole phrase."""
    words = _proper(person)
    if len(words) <= 2:
        return ()
    return tuple(" ".join(words[k:]) for k in range(1, len(words) - 1))


def greeting_name(person: Person) -> str:
    """The name a message greets ``person`` by ("Hi Mai"): the name people use. The office
    says it by the person's first one-word alias that is a word of their full name (Mai for
    "Nguyễn Thị Mai", Wei for "Zhang Wei"): a full name's first word is the family name in
    many languages, so it is used only where no such alias is declared. An alias outside the
    full name ("Boss") or a title is a way to refer to them, not a given name to greet."""
    words = _proper(person)
    own = {w.casefold() for w in words}
    for alias in person.aliases:
        said = alias.split()
        if len(said) == 1 and said[0].casefold() in own and said[0].casefold() not in _TITLES:
            return said[0]
    return words[0] if words else person.name
