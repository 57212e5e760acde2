"""An abbreviation's stop ends no sentence ("Dr. Osei", "e.g. a pen"); a real sentence end
after the same letters, or before a lower-case word after a title, is kept."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.abbreviations import undotted
from helpers.dataset_offices import default_office
from helpers.reading import frame_reader


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("signed by Dr. Osei and then stamped", "signed by Dr Osei and then stamped"),
        ("ask Mrs. Sato. Then print it", "ask Mrs Sato. Then print it"),
        ("for Ms. Émile", "for Ms Émile"),
        ("take it to St. Anne's ward", "take it to St Anne's ward"),
        ("Prof. Lund will sign", "Prof Lund will sign"),
        ("a pen, e.g. a blue one", "a pen, eg a blue one"),
        ("the red one, i.e. mine", "the red one, ie mine"),
        ("approx. ten copies", "approx ten copies"),
        ("get me Luca F.'s costings", "get me Luca F's costings"),
        ("luca f.’s costings", "luca f’s costings"),
    ],
)
def test_the_stop_of_an_abbreviation_is_taken_out(text: str, read: str) -> None:
    assert undotted(text) == read


@pytest.mark.parametrize(
    "text",
    [
        "No. Bring it to me.",
        "see the dr. then go",  # a lower-case word after it: a sentence may end there
        "It is for Ms Sato.",
        "done by Prof.",
        "I need the mrs. form",
        "the end. Dr Osei signs next",
        "it's plan B. Luca's costings",  # no possessive after the letter: a sentence end
    ],
)
def test_other_stops_are_kept(text: str) -> None:
    assert undotted(text) == text


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("leave it w/ Dr Vos", "leave it with Dr Vos"),
        ("W/ Lee please", "with Lee please"),
        ("a tea w/o sugar", "a tea without sugar"),
        ("a tea W/O sugar", "a tea without sugar"),
    ],
)
def test_a_slashed_with_or_without_is_written_out(text: str, read: str) -> None:
    assert undotted(text) == read


@pytest.mark.parametrize(
    "text", ["the rota for w/c 5 May", "print and/or copy", "bring it w/out fail"]
)
def test_other_slashes_are_kept(text: str) -> None:
    assert undotted(text) == text


def test_a_printout_left_w_slash_a_colleague_goes_to_them() -> None:
    frame = frame_reader(default_office, "lee")("pls print my file and leave it w/ Zhang")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "zhang")], frame
