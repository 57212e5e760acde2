"""Stage 3, readings: the lexicon's mentions read in their sentences, and the first doubt."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.readings import MentionReader, Readings
from assistantx.core.office import Office


@pytest.fixture(scope="module")
def read(office: Office) -> Callable[[str], Readings]:
    lex = Lexicon.from_office(office)
    reader = MentionReader(office, lex)

    def reading(text: str) -> Readings:
        return reader.read(lex.read(text))

    return reading


def test_a_later_sentence_naming_one_of_the_people_settles_the_name(
    read: Callable[[str], Readings],
) -> None:
    readings = read("bring me Zhnag's stapler. Zhang Wei")
    people = [m for m in readings.mentions if m.kind == "person"]
    assert [m.ids for m in people] == [("zhang",)]  # the answer is used up
    assert readings.doubt is None


def test_a_name_still_in_doubt_is_the_question_handed_on(read: Callable[[str], Readings]) -> None:
    readings = read("bring me Zhnag's stapler")
    assert readings.doubt is not None
    assert "Zhang Wei" in readings.doubt and "Zheng Hui" in readings.doubt


def test_a_capitalized_name_nobody_here_has_is_asked_about(read: Callable[[str], Readings]) -> None:
    readings = read("take the book to Smith")
    assert readings.doubt == "I don't know anyone called 'Smith' in this office. Who do you mean?"


def test_a_task_word_after_a_possessive_is_the_item(read: Callable[[str], Readings]) -> None:
    readings = read("fetch Mao's seal")
    assert [m.kind for m in readings.mentions][-1] == "item"


@pytest.mark.parametrize(
    ("writer", "text", "meant"),
    [
        ("liu", "send my spreadsheet to Yang please, he asked for the numbers", ("yang",)),
        ("yang", "send my spreadsheet to Yang please", ("liu",)),
        ("mao", "send my spreadsheet to Yang please", ("liu", "yang")),
    ],
)
def test_a_name_the_writer_shares_with_a_colleague_means_the_colleague(
    office: Office, writer: str, text: str, meant: tuple[str, ...]
) -> None:
    """People say "me" of themselves: Liu Yang's "to Yang" is Yang Lei, and the other way
    round; anyone else's "Yang" is still in doubt."""
    lex = Lexicon.from_office(office)
    readings = MentionReader(office, lex).read(lex.read(text), writer)
    people = [m for m in readings.mentions if m.kind == "person"]
    assert [m.ids for m in people] == [meant]
    assert (readings.doubt is None) == (len(meant) == 1)
