"""The speaker's own thing taken away by someone else, told beside a request: "bring me a pen,
the intern borrowed mine", "I need a stapler, the visitor took my one". Such a clause is why
the speaker asks (they are without theirs now), never news that what was asked for is had
already: "borrowed" is a task word of the office ("borrow a pen"), and "mine" after it reads
like "Ida brought me *mine*", so the request was dropped. A verb of taking a thing from its
owner (the language data's ``taking_verbs``, and "borrow") whose subject is not the speaker,
with the speaker's own ("mine", "my ...") right after it, says the speaker lacks it. The
speaker's own taking ("I borrowed one already") is still had."""

from __future__ import annotations

from collections.abc import Collection, Sequence

from assistantx.core import english

# "borrow" is a taking of another's thing too; it is listed apart in the data as the
# requester's own polite verb ("can I borrow ..."), never as a verb of taking away
_TAKING = english.words("taking_verbs") | {"borrow"}
_SPEAKERS_OWN = frozenset({"mine", "my"})
_SPEAKER_SUBJECTS = frozenset({"i", "we", "id", "ive", "wed", "weve", "im"})
# the words that open a clause as its own subject: "... who took mine"
_CLAUSE_SUBJECTS = frozenset({"who", "whoever", "someone", "somebody", "something"})


def taken_from_speaker(words: Sequence[str], at: int, lemmas: Collection[str]) -> bool:
    """Whether the past verb ``words[at]`` (its lemmas ``lemmas``) tells that someone other
    than the speaker took the speaker's own thing: a verb of taking, the speaker's own right
    after it, and no first-person subject before it in the clause."""
    if not set(lemmas) & _TAKING or not set(words[at + 1 : at + 2]) & _SPEAKERS_OWN:
        return False
    # "I'm dying to know *who* took mine": the clause of the verb starts at its wh-word, whose
    # subject it is; the speaker before it only wonders (before, read as the speaker's taking,
    # news that a pen was had, and the request was dropped)
    start = max((n + 1 for n in range(at) if words[n] in _CLAUSE_SUBJECTS), default=0)
    return not set(words[start:at]) & _SPEAKER_SUBJECTS


_MISHAP = english.words("mishap_verbs")
_FALLEN = english.words("fallen_places")
_HANDING = english.words("handing_particles")
_FELL_THINGS = frozenset({"it", "them", "one"})
# how far past a pronoun object the place it fell is looked for ("dropped it *down* the back")
_FALL_REACH = 3


def mishap_to_thing(words: Sequence[str], at: int, lemmas: Collection[str]) -> bool:
    """Whether the past verb ``words[at]`` tells a mishap to a thing, why the speaker asks
    ("I dropped mine down the back of the radiator", "dropped my pen", "dropped it on the
    floor"): a verb of mishap (``mishap_verbs``) with the speaker's own right after it, or a
    pronoun and where it fell; not "drop" with a handing particle after its object ("Ida
    dropped one off already": had)."""
    if not set(lemmas) & _MISHAP:
        return False
    after = list(words[at + 1 : at + 1 + _FALL_REACH + 1])
    if not after or set(after[:3]) & _HANDING:
        return False
    if after[0] in _SPEAKERS_OWN | {"our", "ours"}:
        return True
    return after[0] in _FELL_THINGS and bool(set(after[1:]) & _FALLEN)
