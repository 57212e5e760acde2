"""The particle of a carrying verb is part of the verb: "could you bring some *up* to
reception", "send one *down* to the lab", "fetch a couple *round* to Ed". Said after an object
that stands for a thing named elsewhere ("some", "one", "a couple", "it") and before the
destination's "to", the particle was read as the thing's name ("there is no up to
reception"); it says only the way the robot goes, so it is dropped and "to" opens the
destination, as in "bring some to reception".

Only after such a stand-in and before "to" with no number after it: "it's up to you" (after a
verb "to be") and "up to 5 copies" (a limit) keep their words; after a named item ("bring the
tea up to reception") the reader already reads the particle so. The particles of going across
(``errand_particles``) after "it"/"them" ("run it over to them") are the errand's own and are
kept for its rules; after a quantity ("send some round to ...") they are dropped as well.
"""

from __future__ import annotations

import re

from assistantx.core import english

_PARTICLES = english.words("carrying_particles")
_ACROSS = english.words("errand_particles")
_PRONOUNS = english.words("pronouns")
# the words that stand for a thing named elsewhere by how many: "some", "one", "a couple"
_QUANTITIES = (
    (
        english.words("object_quantifiers")
        | {p.split()[-1] for p in english.entries("another_one")}
        | {"some", "any", "ones"}
    )
    - {"a"}
    - _PRONOUNS
)


def _alternation(words: frozenset[str]) -> str:
    return "|".join(sorted(words))


_CARRIED = re.compile(
    rf"\b(?:(?P<object>{_alternation(_PRONOUNS | _QUANTITIES)})\s+(?:{_alternation(_PARTICLES)})"
    rf"|(?P<quantity>{_alternation(_QUANTITIES)})\s+(?:{_alternation(_ACROSS)}))"
    r"(?=\s+to\s+(?!\d))",
    re.IGNORECASE,
)
# "could you bring some up, ours has gone off", "send one down.": after a quantity, the
# particle ends the clause with no destination said (a pronoun's "pick it up" is left: its
# particle makes another verb)
_CARRIED_TO_NOWHERE = re.compile(
    rf"\b(?P<quantity>{_alternation(_QUANTITIES)})\s+(?:{_alternation(_PARTICLES | _ACROSS)})"
    r"(?=\s*(?:[,.!?;]|$))",
    re.IGNORECASE,
)


def carrying_particles(text: str) -> str:
    """``text`` with a carrying verb's particle between a stand-in object and "to" (or the
    clause's end, after a quantity) dropped."""
    text = _CARRIED.sub(lambda m: m.group("object") or m.group("quantity"), text)
    return _CARRIED_TO_NOWHERE.sub(lambda m: m.group("quantity"), text)
