"""Standing in: "covering the river walk for Fen", "I'm standing in for Fen", "filling in for
Fen today". The person after that "for" is the one the speaker stands in for, the reason for a
request, never whom its thing goes to: the requester, who asks, gets it ("can I get a hi-vis
vest as I'm covering for Fen" is the requester's vest). The person stays named (a hint, a
context); only the recipient's slot is refused.

A cover verb is read in a verb's form ("covering", "covered", "covers", "I cover"), so "a cover
for Fen's laptop", a noun, keeps "for Fen" as whom it is for."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english, language

# "cover for", "sub for": one word before "for" or its object; "stand in for": two.
_COVER_VERBS = english.words("stand_in_verbs")
_IN_VERBS = english.words("stand_in_phrasal_verbs")
# Words that stand before the bare verb form ("I cover for", "to cover for", "I'll sub for").
_SUBJECTS = frozenset({"i", "we", "ill", "im", "to", "will", "can", "could", "must", "ive"})
_LOOK_BACK = 6
_BOUNDARIES = frozenset(
    {"for", "and", "so", "but", "because", "then", "please"}
)  # the cover verb's object sits between it and "for" ("covering chem for Fen")


def stands_in_for(words: Sequence[str], at_for: int) -> bool:
    """Whether the "for" at ``at_for`` follows a verb of standing in for someone, within a
    few words back ("covering chem for", "standing in for", "subbing today for")."""
    if not 0 <= at_for < len(words) or words[at_for] != "for":
        return False
    for k in range(at_for - 1, max(-1, at_for - 1 - _LOOK_BACK), -1):
        word = words[k]
        if word in _BOUNDARIES:
            break  # another phrase begins: its verb is not this "for"'s
        if word == "in" and k == at_for - 1:
            if k > 0 and language.verb_lemmas(words[k - 1]) & _IN_VERBS:
                return True  # "standing in for", "filling in for"
            continue
        lemmas = language.verb_lemmas(word)
        if lemmas & _COVER_VERBS:
            inflected = word not in lemmas
            return inflected or (k > 0 and words[k - 1] in _SUBJECTS)
    return False
