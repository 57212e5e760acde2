"""Whose copy a paper is: "shred Kenji's copy of the contract", "bring me my copy of the
lease". "X's copy of the <paper>" is X's paper itself, said by the copy X holds; the words
"copy of the" only say which of the paper's copies, and are read away before the lexicon, so
the paper is read as "Kenji's contract" (whose it is, and whose consent a change to it needs).
Without the owner's word ("a copy of the contract", "make me a copy of my form") the copy is
still a copy to make; "Kenji's copy" alone is still whatever "copy" names in the office.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

_COPY_NOUNS = english.words("held_copy_nouns")
_OWN_WORDS = english.words("held_copy_owners")
_THE = frozenset({"the", "this", "that"})


def read_held_copies(tokens: Sequence[Token]) -> list[Token]:
    """``tokens`` with "copy of the" dropped after a possessive ("Kenji's", "my", "his")."""
    out: list[Token] = []
    n = 0
    while n < len(tokens):
        t = tokens[n]
        out.append(t)
        words = [x.word for x in tokens[n + 1 : n + 4]]
        owner = t.possessive or t.word in _OWN_WORDS
        if (
            owner
            and len(words) == 3
            and words[0] in _COPY_NOUNS
            and words[1] == "of"
            and words[2] in _THE
            and not any(x.after_pause or x.opens for x in tokens[n + 1 : n + 5])
            and n + 4 < len(tokens)
        ):
            n += 4
            continue
        n += 1
    return out
