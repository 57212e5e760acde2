"""Fixed phrases of English data looked up in a message's words: indexed by their first word,
found at a position, or dropped from the words (hedges, request asides)."""

from __future__ import annotations

from collections.abc import Sequence

PhraseIndex = dict[str, tuple[tuple[str, ...], ...]]


def by_first_word(phrases: Sequence[tuple[str, ...]]) -> PhraseIndex:
    """The phrases by their first word, each word's in the list's order: the reader looks for
    every phrase list at every word of every piece, and only those that start with the word
    there can be said there."""
    index: dict[str, list[tuple[str, ...]]] = {}
    for phrase in phrases:
        if phrase:
            index.setdefault(phrase[0], []).append(phrase)
    return {first: tuple(said) for first, said in index.items()}


def phrase_at(words: Sequence[str], at: int, index: PhraseIndex) -> tuple[str, ...] | None:
    """The first phrase of the list said at ``words[at]``."""
    for phrase in index.get(words[at], ()):
        if tuple(words[at : at + len(phrase)]) == phrase:
            return phrase
    return None


def without_phrases(words: Sequence[str], index: PhraseIndex) -> list[str]:
    """``words`` less every phrase of ``index`` said in them (the first listed wins where two
    start at one word)."""
    kept: list[str] = []
    n = 0
    while n < len(words):
        phrase = phrase_at(words, n, index)
        if phrase is None:
            kept.append(words[n])
            n += 1
        else:
            n += len(phrase)
    return kept
