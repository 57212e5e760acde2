"""The English word lists are package data (``data/english.yaml``), read once (issue 16)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.lexicon import COMMON, CUES
from assistantx.core import english
from assistantx.memory.names import TITLES, normalize


def test_the_parser_and_name_matcher_read_their_words_from_the_data_file() -> None:
    assert TITLES == english.words("titles")
    assert COMMON == english.words("common")
    assert CUES == english.word_table("cues")
    assert {"dr", "professor"} <= TITLES
    assert {"no", "on", "off", "yes"} <= COMMON  # quoted in YAML, so words and not booleans


def test_the_file_is_read_once() -> None:
    assert english.entries_of() is english.entries_of()


def test_an_unknown_list_is_a_clear_error() -> None:
    with pytest.raises(KeyError, match="no list 'nonsense'"):
        english.entries("nonsense")
    with pytest.raises(KeyError, match="no word table 'titles'"):
        english.word_table("titles")


def test_titles_are_taken_off_names() -> None:
    assert normalize("Dr. Zhang") == normalize("Professor  ZHANG") == "zhang"
