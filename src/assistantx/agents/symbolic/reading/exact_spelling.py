"""An exact spelling tells two people apart whose names differ only by diacritics.

The lexicon folds names ("Tomás" and "Tomáš" are both ``tomas``) so that a writer without
the marks still finds the person. A writer who types the marks, though, has spelled one of
them: "Tomás" is how Tomás Herrera writes his name and not how Tomáš Novák writes his. So of
several people a folded name means, those whose own spelling is exactly the written one are
meant, when some but not all are. A name written without any mark ("Tomas") says nothing of
which spelling was meant and stays ambiguous (asked)."""

from __future__ import annotations

import unicodedata
from collections.abc import Iterable, Mapping, Sequence

from assistantx.core.office import Office, Person


def _spelled(text: str) -> str:
    """The word as written, case aside: composed (NFC) so that "á" typed as one character or
    as "a" and a combining accent is the same spelling; possessive and apostrophes dropped."""
    word = unicodedata.normalize("NFC", text.replace("’", "'")).casefold()
    if word.endswith("'s"):
        word = word[:-2]
    return word.rstrip("'")


def _marked(word: str) -> bool:
    """Whether a written word carries a diacritic (a letter beyond plain ASCII)."""
    return any(ord(c) > 127 and c.isalpha() for c in word)


def _own_words(office: Office, person: str) -> frozenset[str]:
    p = office.person(person)
    return frozenset(_spelled(w) for name in (p.name, *p.aliases) for w in name.split())


def own_spellings(office: Office) -> dict[str, frozenset[str]]:
    """Each colleague's own words of their name and aliases, as they spell them: what
    ``spelled_by`` tells namesakes apart with, worked out once by a reader that keeps it."""
    return {p.id: _own_words(office, p.id) for p in office.people}


def spelled_by(
    spellings: Mapping[str, frozenset[str]], written: Iterable[str], ids: Iterable[str]
) -> frozenset[str]:
    """``exactly_spelled`` with the colleagues' spellings given (``own_spellings``): of
    ``ids``, those who spell every written word so, where a diacritic was typed and that
    leaves some but not all of them; else ``ids``. The consent guard reads names with it,
    so "Sofía" is Sofía Ramírez there too, never also Sofia Kowalczyk."""
    ids = frozenset(ids)
    words = [_spelled(w) for w in written]
    if len(ids) < 2 or not any(_marked(w) for w in words):
        return ids
    exact = frozenset(i for i in ids if all(w in spellings.get(i, ()) for w in words))
    return exact if exact and exact != ids else ids


def exactly_spelled(office: Office, written: Iterable[str], ids: Sequence[str]) -> tuple[str, ...]:
    """Of ``ids`` (people one folded name means), those whose own names spell every written
    word exactly, where the writer typed a diacritic and that leaves some but not all of
    them. Where none of ``ids`` spells it so (Tomás Herrera's alias "Tomás" won the folded
    "tomas", but "Tomáš" was typed), the colleagues who do spell it so. Else ``ids``."""
    words = [_spelled(w) for w in written]
    if not ids or not any(_marked(w) for w in words):
        return tuple(ids)

    def spells(person: str) -> bool:
        return all(w in _own_words(office, person) for w in words)

    exact = tuple(i for i in ids if spells(i))
    if not exact:
        return tuple(p.id for p in office.people if spells(p.id)) or tuple(ids)
    return exact if len(exact) < len(ids) else tuple(ids)


def called_as_written(person: Person, written: str) -> bool:
    """Whether ``person`` is called by ``written`` spelled exactly so, diacritics and all
    (case and a possessive aside): their name's first word or a one-word alias ("Sean" for
    Sean Baker; for Seán O'Connell, declared "Seán", only "Seán")."""
    first = person.name.split()[:1]
    declared = [a for a in person.aliases if " " not in a.strip()]
    return _spelled(written) in {_spelled(w) for w in (*first, *declared)}


def plainly_called(
    people: Iterable[Person], chosen: frozenset[str] | set[str], written: str
) -> set[str]:
    """ "sean" beside Seán O'Connell, declared "Seán", and Sean Baker, called Sean: a bare
    alias wins a folded name, but where it carries diacritics the writer did not type, none of
    ``chosen`` is called as written, and those of ``people`` who are called so exactly (Sean
    Baker) are meant as well: folded, the two are one word, and people drop accents, so which
    is asked. Else ``chosen`` as it is."""
    if not _marked(_spelled(written)) and not any(
        called_as_written(p, written) for p in people if p.id in chosen
    ):
        return set(chosen) | {p.id for p in people if called_as_written(p, written)}
    return set(chosen)
