"""Whether a colleague is called by a one-word name, or only has it somewhere in their name.

Colleagues are called by their first name or by a name the office declares for them ("Cliff"
is how Cliff Adebayo is called; Marcus Cliff is called Marcus, whatever his family name). When
a word is one colleague's first name and another's later name word, what an item says of its
owner ("cliff's running order", where only Marcus Cliff keeps one) is no reason to take the
one who is not called so without asking: the requester most likely meant the one they call
Cliff, who may just not be known to keep one. Nor is it when several are called by the word
("Noor" for Noor Haddad and for Noor Salem): the assistant's record is of what it knows, not of
all anyone owns, so the other may well keep one too; the requester is asked which.
"""

from __future__ import annotations

from assistantx.core import language
from assistantx.core.office import Person


def called_by(person: Person, word: str) -> bool:
    """Whether ``person`` is called ``word`` (folded): their name's first word or a one-word
    name the office declares for them."""
    first = person.name.split()[0] if person.name.split() else ""
    declared = {language.fold(a) for a in person.aliases if " " not in a.strip()}
    return word == language.fold(first) or word in declared


def only_in_full_name(person: Person, others: list[Person], word: str) -> bool:
    """Whether ``word`` names ``person`` only as a later word of their full name while one of
    ``others`` is called by it ("Cliff" for Marcus Cliff beside Cliff Adebayo)."""
    return not called_by(person, word) and any(called_by(o, word) for o in others)


def called_alike(person: Person, others: list[Person], word: str) -> bool:
    """Whether ``person`` is called ``word`` and so is one of ``others`` ("Noor" for Noor
    Haddad and Noor Salem): the word alone says neither."""
    return called_by(person, word) and any(called_by(o, word) for o in others)
