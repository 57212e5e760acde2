"""A correction said with a sound before it ("oh wait no, Wang's") or naming a new thing and
then whose it is ("no wait, scissors - sun's if she's around") replaces the thing and its
owner: never a withdrawal of the whole request, nor anyone's thing beside the owner's
(``reading.possessive_corrections``, ``reading.screen.correction``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "mao")
_HARBOUR = frame_reader(harbour_office, "rose")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str]]:
    return sorted((t.kind, t.item, t.owner, t.recipient) for t in getattr(frame, "tasks", []))


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("bring me Zhang's stapler, oh wait no, Wang's", "stapler", "wang"),  # analogue
        ("bring me Zhang's stapler, um sorry, Wang's", "stapler", "wang"),
        ("could you get me Lee's book, oh no wait, Hu's", "book", "hu"),
        ("can i borrow a pen? no wait, scissors - sun's if she's around", "scissors", "sun"),
        ("can i borrow a stapler? no wait, scissors - chen's", "scissors", "chen"),
        ("can i borrow a pen? no wait, scissors, Chen's", "scissors", "chen"),
        ("could you bring me a book? sorry, stapler - Hu's", "stapler", "hu"),
        ("can i borrow a pen? no wait, Chen's scissors", "scissors", "chen"),
    ],
)
def test_the_corrected_thing_is_the_named_owners(text: str, item: str, owner: str) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("transfer", item, owner, "mao")], frame


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("bring me Mark's ruler, oh wait no, Ken's", "ruler", "ken"),
        ("can i borrow a ruler? no wait, calculator - ken's", "calculator", "ken"),
        (
            "can i borrow a ruler? no wait, calculator - lindqvist's if he's around",
            "calculator",
            "mark",
        ),
    ],
)
def test_harbour_the_corrected_thing_is_the_named_owners(text: str, item: str, owner: str) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("transfer", item, owner, "rose")], frame


def test_a_withdrawal_with_no_choice_after_it_still_withdraws() -> None:
    frame = _DEFAULT("bring me Zhang's stapler, oh wait no, forget it")  # must not change
    assert frame.tasks == [], frame


def test_a_possessive_with_a_thing_of_its_own_is_a_second_thing() -> None:
    frame = _DEFAULT("bring me Zhang's stapler and Wang's scissors")  # must not change
    assert _tasks(frame) == [
        ("transfer", "scissors", "wang", "mao"),
        ("transfer", "stapler", "zhang", "mao"),
    ], frame
