"""A correction of whose thing it is ("..., no wait, Mai's") replaces the whole name said
before, given name and surname ("Tom Hughes's"), never only its last word: round 243 kept
"Tom" ("bring me Tom Mai's radio") and asked which Tom was meant. Two names side by side
("give Tom Mai's radio") are no one name, and a possessive alone is corrected as before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.possessive_corrections import possessive_corrections
from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "sun")
_PEOPLE = frozenset({"zhang", "wei", "wang", "tom", "mai", "hu", "gao"})


def _is_person(word: str) -> bool:
    return word.lower().removesuffix("'s") in _PEOPLE


def _one_name(phrase: str) -> bool:
    return phrase.lower().removesuffix("'s") in {"zhang wei", "tom hughes"}


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("bring me Zhang Wei's stapler, no wait, Wang's", "bring me Wang's stapler"),
        ("bring me Hu's stapler, Gao's", "bring me Gao's stapler"),
    ],
)
def test_the_whole_name_is_corrected(text: str, said: str) -> None:
    assert possessive_corrections(text, _is_person, _one_name).rstrip(", ") == said


def test_without_whole_names_only_the_possessive_is_known() -> None:
    # the step read alone, with no reading of whole names: the last word, as before
    out = possessive_corrections("bring me Zhang Wei's stapler, no wait, Wang's", _is_person)
    assert out.startswith("bring me Zhang Wang's stapler"), out


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me Zhang Wei's stapler, no wait, Wang's", "wang"),
        ("can you bring me Zheng Hui's stapler, no wait, Mao's, hers is broken", "mao"),
    ],
)
def test_the_reader_takes_the_new_owner(text: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.item, t.owner) for t in frame.tasks] == [("stapler", owner)], frame
