"""A thing named by another English word for its head noun: "a charging lead", "a charger
cord" where the office's data cable is called "charging cable" and "charger cable". People
name the same thing by the word for its head noun they use ("lead", "cord" of a cable:
``head_synonyms`` in the English data) after the office's own modifier; read as a thing the
office does not have ("Sorry, there is no charging lead"), the need went unmet.

Only names of two words or more are varied: a bare "lead" (of a pencil, of a dog) or "cord"
stays what it was. A form that two things would take is neither's, and a form the office
already names something by keeps its own reading."""

from __future__ import annotations

from collections.abc import Collection, Iterable

from assistantx.core import english

# the English words for one head noun: "lead", "cord" are said of a cable, and the other way
_OTHERS: dict[str, frozenset[str]] = {}
for _head, _words in english.phrase_table("head_synonyms").items():
    for _word in (_head, *_words):
        _OTHERS[_word] = _OTHERS.get(_word, frozenset()) | ({_head, *_words} - {_word})


def head_synonyms(names: Iterable[tuple[str, str]], used: Collection[str]) -> dict[str, str]:
    """The further names of the office's things: each name of two words or more said with
    another word for its head noun ("charging lead" of "charging cable"); ``names``: (name,
    type id), folded; ``used``: what the office already names something by."""
    found: dict[str, set[str]] = {}
    for name, type_id in names:
        words = name.split()
        if len(words) < 2:
            continue
        for other in _OTHERS.get(words[-1], ()):
            found.setdefault(" ".join([*words[:-1], other]), set()).add(type_id)
    return {form: ids.pop() for form, ids in found.items() if len(ids) == 1 and form not in used}
