"""The screen's word lists: phrases as tuples of words, the longest tried first."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import english, split_words, starts_with


def test_phrases_are_tried_longest_first_so_throw_away_wins_over_throw() -> None:
    destructive = english().destructive
    assert ("throw", "away") in destructive
    lengths = [len(p) for p in destructive]
    assert lengths == sorted(lengths, reverse=True)


def test_a_phrase_starts_at_a_word_only_where_all_its_words_follow() -> None:
    words = split_words("please throw away the pen")
    assert starts_with(words, 1, ("throw", "away"))
    assert not starts_with(words, 0, ("throw", "away"))
    assert not starts_with(words, 4, ("pen", "please"))  # runs past the end
