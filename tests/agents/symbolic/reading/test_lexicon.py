"""Stage 2, lexicon: tokens → the office's words (people, items, facilities, places, task
words), with typos corrected against that office only."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.lexicon import Lexed, Lexicon
from assistantx.core.office import Office


@pytest.fixture(scope="module")
def lex(office: Office) -> Lexicon:
    return Lexicon.from_office(office)


def _kinds(lexed: Lexed) -> list[tuple[str, tuple[str, ...]]]:
    return [(m.kind, m.ids) for m in lexed.mentions if m.kind != "word"]


def test_people_items_facilities_and_task_words_are_found_by_the_offices_names(
    lex: Lexicon,
) -> None:
    lexed = lex.read("please print my report at the photocopier for Zhang Wei")
    assert isinstance(lexed.tokens, tuple) and isinstance(lexed.mentions, tuple)
    assert ("cue", ("print",)) in _kinds(lexed)
    assert ("facility", ("printer",)) in _kinds(lexed)  # a synonym of the office's printer
    assert ("person", ("zhang",)) in _kinds(lexed)
    assert ("self", ()) in _kinds(lexed)


def test_a_typo_is_corrected_to_an_office_word_and_remembers_what_was_typed(
    lex: Lexicon,
) -> None:
    lexed = lex.read("bring me a stapeler")
    token = lexed.tokens[-1]
    assert (token.typed, token.word, token.corrected) == ("stapeler", "stapler", True)
    assert _kinds(lexed)[-1] == ("item", ("stapler",))


def test_a_name_several_people_may_mean_is_kept_ambiguous_never_guessed(lex: Lexicon) -> None:
    lexed = lex.read("bring me Zhnag's stapler")
    people = [m for m in lexed.mentions if m.kind == "person"]
    assert len(people) == 1 and set(people[0].ids) == {"zhang", "zheng"}
