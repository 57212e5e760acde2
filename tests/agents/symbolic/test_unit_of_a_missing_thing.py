"""A thing the office lacks, said by a unit of it ("a sheet of paper", "a box of staples"), beside
a thing it has (fix213b class 3): "bring me a tea and a sheet of paper" in an office with no
paper brought the tea alone, the paper dropped unsaid (the phrase stopped at "of", so it was
read as no thing). What a unit is of is the thing (``unnamed_things._unit_of``): it is asked
about as "a unicorn" beside a stapler is, never dropped."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("office", "who", "text", "said"),
    [
        ("harbour", "may", "bring me a tea and a sheet of paper", "a sheet of paper"),
        ("harbour", "may", "bring me a ruler and a sheet of paper", "a sheet of paper"),
        ("default", "lee", "bring me a coffee and a box of staples", "a box of staples"),
    ],
)
def test_the_missing_thing_is_said(office: str, who: str, text: str, said: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == []
    assert frame.question == f"Sorry, I'm not sure what you mean by “{said}”. Could you tell me?"


def test_neighbour_the_office_s_own_paper_is_brought() -> None:
    assert tasks_of("default", "bring me a coffee and a sheet of paper", "lee") == [
        ("produce", "coffee", None, "lee"),
        ("transfer", "paper", None, "lee"),
    ]


def test_neighbour_a_unit_of_the_office_s_thing_is_that_thing() -> None:
    tasks = tasks_of("harbour", "bring me a tea and a pad of paper", "may")
    assert [t[1] for t in tasks] == ["tea", "notepad"]
