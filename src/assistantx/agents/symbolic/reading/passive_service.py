"""A service asked for in the passive: "could the proofs be comb-bound?", "can these proofs
get laminated?", "could my report be spiral-bound for me?".

"Could the badge be ...?" opens like "will Ray be in tomorrow?" (a modal, a subject, "be"),
which asks to be told something. But where the word after "be" or "get" is the participle of
one of the office's own services, the speaker asks for that work done to the thing: nobody
asks whether a badge *could* be laminated in an office whose laminator is there to do it.
The participle may carry a hyphenated prefix that says how ("comb-bound", "heat-sealed"),
which the tokenizer splits off as a word of its own. Only "can"/"could" ask: "will my report
be bound by Friday?" and "has my report been bound yet?" ask about its state, and "could it
have been laminated?" (no "be"/"get" right before the participle) is a guess about the past.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import language

_ASKING_MODALS = frozenset({"can", "could", "cud", "cn"})
# the passive's auxiliary: "be bound", "get laminated"
_PASSIVE = frozenset({"be", "get"})
# how far the auxiliary may stand from the modal: "could *the two proofs of mine* be ..."
_SUBJECT_REACH = 6


def service_asked_in_passive(w: Sequence[str], service_words: frozenset[str]) -> bool:
    """Whether ``w`` (a piece's words, openers dropped) is "can/could <thing> be/get
    [<prefix>] <participle of an office service>"."""
    if len(w) < 4 or w[0] not in _ASKING_MODALS:
        return False
    for k in range(2, min(len(w), _SUBJECT_REACH + 2)):
        if w[k] not in _PASSIVE:
            continue
        # the participle itself, or after one word of a hyphenated prefix ("comb bound")
        return any(_service_participle(x, service_words) for x in w[k + 1 : k + 3])
    return False


def _service_participle(word: str, service_words: frozenset[str]) -> bool:
    return word in service_words and language.is_past_participle(word)
