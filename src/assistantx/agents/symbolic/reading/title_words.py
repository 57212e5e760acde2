"""A capitalised word inside a title is a word of the name of a thing, never a colleague to
look up: "apply this week's Notices to Mariners corrections", "print the Code of Practice
doc", "the Rules of the Road leaflet".

A title is a run of capitalised words, its small words ("to", "of", "the") in lower case or
not. A capitalised word that names nobody in the office is read as part of it where the word
right before it is capitalised too (mid-sentence, so not capitalised only for opening it),
or where "to"/"of" (and an article) stands between it and a capitalised word: "Notices *to
Mariners*". The word before must name nothing of the office itself, a colleague or a thing
("give the Report to Mariners" keeps its question: "the Report" is a thing and "to" hands it
on); a colleague's name after "to" ("give the Terms of Reference to Ana") is read as the
colleague, since only names of nobody come here.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token

_JOINS = frozenset({"to", "of"})
_ARTICLES = frozenset({"the", "a", "an"})


def inside_a_title(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """Whether ``mentions[n]`` (a capitalised word naming nobody) continues a title."""
    at = mentions[n].start
    k = at - 1
    while k > 0 and tokens[k].word in _ARTICLES and k >= at - 1:
        k -= 1  # "of *the* Road"
    if k > 0 and tokens[k].word in _JOINS and k < at:
        k -= 1  # "Notices *to* Mariners"
    elif k != at - 1:
        return False  # an article alone before it: "the Mariners" is no title's inside
    if k < 0 or tokens[k].after_pause or tokens[at].after_pause:
        return False
    before = tokens[k]
    if not before.text[:1].isupper() or before.opens or k == 0:
        return False  # "Ask Mariners ...": capitalised only for opening the sentence
    owner = next((m for m in mentions if m.start <= k < m.end), None)
    return owner is not None and owner.kind == "word" and not owner.possessive
