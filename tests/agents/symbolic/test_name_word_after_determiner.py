"""A colleague's surname that is also an English noun the dictionary lacks ("cox", listed in
english.yaml ``dictionary_gap_nouns``) has a word reading, read by its syntax as any name word
that is a word ("mason") is: lowercase after a determiner or possessive ("our cox", "the
cox") it is the word, so "Our cox is off sick" notes nobody away and Harriet Cox is still
asked for her cox box. Capitalised ("our Cox") or bare ("Cox is off sick") it stays her.
On a small office (helpers.dive_van)."""

from __future__ import annotations

import pytest

from helpers.dive_van import dive_van
from helpers.reading import frame_reader

_van = frame_reader(dive_van, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "Our cox is off sick. Could you grab me a cox box?",
        "our cox is off sick, could you grab me a cox box",
        "the cox is away today, can you get me a cox box",
        "my cox is off sick so could you fetch me a cox box",
    ],
)
def test_a_lowercase_name_word_after_a_determiner_is_the_word(text: str) -> None:
    frame = _van(text)
    assert frame.away() == set(), frame.explain()
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "cox_box", "lee")
    ], frame.explain()


@pytest.mark.parametrize(
    "text",
    [
        "our Cox is off sick",  # capitalised: the colleague, as today
        "Cox is off sick",  # bare, as a subject: the colleague
        "Ruth Mason is off sick",
    ],
)
def test_a_capitalised_or_bare_name_is_still_the_colleague(text: str) -> None:
    frame = _van(text)
    assert frame.away(), frame.explain()


def test_the_mason_after_the_article_is_no_colleague() -> None:
    # must not change: "mason" is a dictionary word, already read as the word
    assert _van("the mason is off sick").away() == set()
