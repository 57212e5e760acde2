"""A question for a thing the asker can use at a time later the same day: "anyone got a
calculator I can use this afternoon?", "does anyone have scissors I could use later today?".
The time is when the thing is used, not when it is handed over, so it is had by then: the
question asks for one now, as "... for tonight" does (``future_need.without_events``). A verb
of the hand-over keeps its time ("... a ruler I could borrow this afternoon?" is borrowed
then, answered), and a time on another day is too far off to hold a colleague's thing for
("... I could use tomorrow?" is answered, as before); "later" alone names no day and waits.

The words are English's, from ``data/english.yaml``; nothing here knows an office."""

from __future__ import annotations

from assistantx.core import english

_USE = english.words("use_verbs")
_TODAY = tuple(tuple(p.split()) for p in english.entries("same_day_times"))
# the words that may stand between the verb of use and its time ("use it this afternoon")
_BETWEEN = frozenset({"it", "one", "them", "for", "a", "bit", "briefly", "quickly"})


def used_later_today(words: list[str]) -> bool:
    """Whether ``words`` say a use by the speaker at a time later today (a verb of
    ``use_verbs``, then a time of ``same_day_times`` a few words on)."""
    for n, w in enumerate(words):
        if w not in _USE:
            continue
        k = n + 1
        while k < len(words) and words[k] in _BETWEEN:
            k += 1
        if any(tuple(words[k : k + len(t)]) == t for t in _TODAY):
            return True
    return False
