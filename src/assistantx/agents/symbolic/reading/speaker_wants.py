"""The speaker as the one who wants the thing: "I need a ruler for a friend", "I'd like a tea
for my guest", "can I have a pen for a visitor?", "we could do with a stapler".

A "for" phrase beside such a want says whom the thing is for in the end, not whom it is
handed to: the speaker said they are the one in need, so the thing comes to them, who pass it
on. Only the speaker as the subject of wanting counts ("I", "we" and a verb of wanting, or a
modal asking for oneself: "can I have/get/borrow"); "bring a tea for the visitor" names no
one in need and is asked about as before."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english

_SPEAKER = frozenset({"i", "we"})
_NEEDS = english.words("need_verbs")
# "I'd like", "we would love", "I could use / do with": a want with a helping verb
_HELPED = (
    *(tuple(p.split()) for p in english.entries("modal_wants")),
    ("d", "like"),
    ("d", "love"),
)
_MODALS = english.words("request_modals")
# "can I have / get / borrow": the speaker asks for the thing for themself
_TAKING = frozenset({"have", "get", "borrow", "take", "grab"})
_ADVERBS = frozenset({"really", "just", "also", "still", "urgently", "badly"})


def speaker_wants(words: Sequence[str]) -> bool:
    """Whether ``words`` (lowercase) have the speaker as the subject of a want of a thing
    ("I need a ruler", "I'd like a tea", "can I have a pen"); not what the speaker must do
    ("I need to send ...")."""
    for n, word in enumerate(words):
        if word not in _SPEAKER:
            continue
        if n > 0 and words[n - 1] in _MODALS:
            if words[n + 1 : n + 2] and words[n + 1] in _TAKING:
                return True  # "can I have a pen"
        k = n + 1
        while k < len(words) and words[k] in _ADVERBS:
            k += 1
        rest = tuple(words[k:])
        if rest[:1] and rest[0] in _NEEDS:
            if rest[1:2] != ("to",):
                return True  # "I need a ruler", not "I need to sign in"
        elif any(rest[: len(p)] == p for p in _HELPED):
            return True
    return False
