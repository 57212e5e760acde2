"""The owner of the thing carried to someone is not whom it is carried to.

"Pat's tape ran out, can you take May's over to her?", "Lin's scissors are blunt, bring
Chen's over to him": the possessive right before the carrying ("May's", with its noun said
or left out) names whose thing goes; a "him"/"her" after "to" is someone else, the one named
before. English says the owner as the receiver only with "back" ("get Zofia's back to her":
it goes home), so a particle of the way ("over", "round", "down") keeps the owner out, and
"back" keeps them in.

The reader's screen (``screen.rewrites._source``, which names the pronoun back) and the
runtime's consent guard (``runtime.recipients``, which lets the hand-over go to the one the
pronoun means) decide with this one function, so the guard allows what the reader planned.
"""

from __future__ import annotations

from collections.abc import Container, Sequence

from assistantx.core import english

# "over", "across", "round", "up", "down", "along": the way the thing goes, never "back"
_WAY = (english.words("errand_particles") | english.words("carrying_particles")) - {"back"}
_TO = "to"
_LONGEST = 4  # the words of an item's name said after the possessive ("label maker")


def carried_to(words: Sequence[str], at: int, items: Container[str] = ()) -> int | None:
    """The index of the "to" that the thing owned by the possessive ending at ``at`` is
    carried to: after the possessive, its noun (words of ``items``, none where the noun is
    left out: "May's over to her"), at most one particle of the way, then "to". None where
    anything else follows ("May's back to her", "May's is broken")."""
    k = at
    while k < len(words) and k - at < _LONGEST and words[k] in items:
        k += 1
    if k < len(words) and words[k] in _WAY:
        k += 1
    return k if k < len(words) and words[k] == _TO else None
