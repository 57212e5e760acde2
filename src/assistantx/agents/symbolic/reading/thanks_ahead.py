"""Thanks in advance for what is asked: "I'd be grateful for a box of staples when you get a
sec", "we'd appreciate a ruler from the stores". Gratitude in the conditional ("I'd", "we'd",
"I would") is for something not yet done, so it asks for what follows; gratitude for what was
done ("grateful for your help yesterday", "I'm grateful for the staples", "I'd appreciate
it" after an offer) is thanks, answered in words."""

from __future__ import annotations

from assistantx.core import english

_THANKS = english.words("thanks_words")
_PAST_TIMES = tuple(tuple(p.split()) for p in english.entries("past_times"))
# The speaker's conditional before the gratitude ("I'd be grateful", "we would appreciate").
_CONDITIONAL = frozenset({"id", "wed", "would"})
# What the gratitude may be for with nothing asked: the offer just made ("I'd appreciate it").
_THE_OFFER = frozenset({"it", "that", "this", "so", "much", "very", "greatly", "truly", "lot"})
# How far into the piece the gratitude may stand ("I would be very grateful for ...").
_REACH = 5


def _past(words: list[str]) -> bool:
    return any(tuple(words[n : n + len(p)]) == p for n in range(len(words)) for p in _PAST_TIMES)


def thanks_ahead(words: list[str]) -> bool:
    """Whether ``words`` (the piece's content words) give thanks in advance for something
    they ask for: a conditional before the first gratitude word, and a thing after it."""
    at = next((n for n, w in enumerate(words[:_REACH]) if w in _THANKS), None)
    if at is None or not _CONDITIONAL.intersection(words[:at]):
        return False
    rest = [w for w in words[at + 1 :] if w not in ("for", "of", "a", "lot")]
    if not rest or all(w in _THE_OFFER for w in rest):
        return False
    return not _past(rest)
