"""Stage 1, tokens: the words of any script, their folded keys and where sentences open."""

from __future__ import annotations

import dataclasses

import pytest

from assistantx.agents.symbolic.reading.tokens import gaps, prev_word, tokenize


def test_words_of_any_script_keep_their_spelling_and_fold_to_one_key() -> None:
    tokens = tokenize("Bring José Müller’s stapler")
    assert [t.text for t in tokens] == ["Bring", "José", "Müller's", "stapler"]
    assert [t.word for t in tokens] == ["bring", "jose", "muller", "stapler"]
    assert [t.possessive for t in tokens] == [False, False, True, False]


def test_a_token_is_uncorrected_and_cannot_be_changed() -> None:
    (token,) = tokenize("stapeler")
    assert token.typed == token.word == "stapeler" and not token.corrected
    with pytest.raises(dataclasses.FrozenInstanceError):
        token.word = "stapler"  # type: ignore[misc]
    assert token.corrected_to("stapler").corrected


def test_sentences_open_after_a_full_stop_and_a_titles_stop_ends_none() -> None:
    text = "Ask Dr. Zhang. Then print it"
    tokens = tokenize(text)
    assert [t.word for t in tokens if t.opens] == ["ask", "zhang", "then"]
    spaces = gaps(text, tokens)
    assert spaces[2] == " "  # "Dr." before Zhang: no sentence end for the later stages
    assert "." in spaces[3]
    assert prev_word(tokens, 2) == "ask"  # the title is skipped
    assert prev_word(tokens, 2, skip_titles=False) == "dr"
