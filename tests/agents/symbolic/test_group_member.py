"""One of a group as a clause's subject is one person named by what they are ("one of the
interns spilled coffee on the stapler" is told as "an intern spilled ..."):
``reading.group_member``. Read with "one of the" in front, the clause was no statement and
the things it named were fetched besides the thing asked (blind round 193: a puck brought
with the ice pack). "bring me one of the staplers" keeps its reading."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from assistantx.agents.symbolic.reading.group_member import group_member


@pytest.mark.parametrize(
    "text",
    [
        "Bring me a cup please, one of the interns spilled coffee on the stapler.",
        "bring me a cup pls. one of the visitors took mine",
        "could I get a cup? one of the trainees knocked mine off the desk",
    ],
)
def test_only_the_thing_asked_is_brought(text: str) -> None:
    assert tasks_of("default", text, "lee") == [("transfer", "cup", None, "lee")]


def test_one_of_the_things_is_still_one_of_them() -> None:
    assert tasks_of("default", "bring me one of the staplers", "lee") == [
        ("transfer", "stapler", None, "lee")
    ]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("one of the juniors took a puck", "a junior took a puck"),
        ("One of the interns spilled it", "An intern spilled it"),
        ("bring me one of the staplers", "bring me one of the staplers"),
        ("one of the staplers is broken", "one of the staplers is broken"),  # the office's
    ],
)
def test_the_rewrite(text: str, expected: str) -> None:
    assert group_member(text, frozenset({"staplers", "stapler"})) == expected
