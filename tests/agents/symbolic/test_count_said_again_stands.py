"""Fixer fix59c class 4: a count said again after a request ("get me two pens, no wait, just
one is fine", "three copies of my form please, no actually two is enough") corrects the
count, never withdraws the request (``screen.withdrawal``); "three copies" names how many,
never a variant of a copy (``screen.variant``). A withdrawal after "no wait" ("never mind")
and a thing corrected ("not pens, pencils") are read as before."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("get me two pens, no wait, just one is fine", [("transfer", "pen", None, "lee")]),
        ("bring me two pens, no wait just one", [("transfer", "pen", None, "lee")]),
        ("bring me three pens. wait no, two is enough", [("transfer", "pen", None, "lee")]),
        (
            "three copies of my form please, no actually two is enough",
            [("copy", "document", "lee", "lee")],
        ),
        (
            "print me three copies of my form, no wait, actually two is enough",
            [("print", "file", "lee", "lee")],
        ),
        ("make me three copies of my form", [("copy", "document", "lee", "lee")]),
        # a neighbour read so already
        ("get me a couple of pens, oh no just one is fine", [("transfer", "pen", None, "lee")]),
    ],
)
def test_the_request_stands(text: str, tasks: list[tuple[str, str, str | None, str]]) -> None:
    assert tasks_of("default", text, "lee") == tasks


@pytest.mark.parametrize(
    "text",
    ["bring me two pens, no wait, never mind", "bring me two pens, no wait, not pens, pencils"],
)
def test_a_withdrawal_still_drops_it(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.decline is not None and "dropped" in frame.decline, frame
