"""An abbreviation's stop ends no sentence ("Dr. Osei", "e.g. a pen"); a real sentence end
after the same letters, or before a lower-case word after a title, is kept."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.abbreviations import undotted


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
