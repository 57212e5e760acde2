"""'get Priya a coffee', 'bring Tomasz the spare key': a capitalised name between a verb of
handing and the thing handed is whom it is for; where nobody of the office is so called it is
asked about ("I don't know anyone called 'Priya'"), as a name after "for" is, never dropped
so that the thing went to the speaker. A colleague so named still gets it, a misspelt one is
asked which, and a name said elsewhere is read as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "sun")


@pytest.mark.parametrize(
    ("text", "name"),
    [
        ("get Priya a coffee", "Priya"),
        ("bring Tomasz the spare key", "Tomasz"),
        ("could you make Olu a coffee please", "Olu"),
        ("hand Ines some paper", "Ines"),
        ("get Priya my stapler", "Priya"),  # the thing opened by whose it is
        ("find Tomasz a seat", "Tomasz"),  # any verb that takes whom a thing is for
    ],
)
def test_an_unknown_receiver_is_asked(text: str, name: str) -> None:
    frame = _frame(text)
    assert not frame.tasks, frame
    assert frame.question == f"I don't know anyone called {name!r} in this office. Who do you mean?"


def test_a_misspelt_colleague_is_asked_which() -> None:
    frame = _frame("get Zhnag a coffee")
    assert frame.question == "Who do you mean by 'Zhnag': Zhang Wei or Zheng Hui?"


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("get Mao a coffee", "mao"),
        ("bring me a coffee", "sun"),
        ("get a coffee for Mao", "mao"),
    ],
)
def test_must_not_change(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert [t.recipient for t in frame.tasks] == [recipient], frame
