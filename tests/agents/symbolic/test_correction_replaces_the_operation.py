"""A correction that says another operation for the same thing ("print my document for me - no
wait, it's the paper one, photocopy it instead", "copy my file - sorry, I mean print it"):
the operation said last runs on the thing of the one withdrawn (``screen.correction``). A
clause that only says what the thing is ("it's the paper one") before the correcting request
is no correction of the thing; "it" followed by "instead" or "please" is still that thing.
A clause that says whose it is ("it's Gao's") still corrects the owner."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    "text",
    [
        "print my document for me - no wait, it's the paper one, photocopy it instead",
        "print my contract - no wait, photocopy it instead",
        "print my document - actually, it's a paper one, copy it instead",
        "print my report - no, copy it please",
    ],
)
def test_the_operation_said_last_runs_on_the_paper_default(text: str) -> None:
    assert tasks_of("default", text, "zhang") == [("copy", "document", "zhang", "zhang")]


@pytest.mark.parametrize(
    "text",
    ["copy my file - sorry, I mean print it", "photocopy my file - sorry, I meant print it please"],
)
def test_a_print_said_last_prints_the_file_default(text: str) -> None:
    assert tasks_of("default", text, "zhang") == [("print", "file", "zhang", "zhang")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "print my letter - no wait, it's a paper one, scan it instead",
            [("copy", "document", "may", "may")],
        ),
        ("print my form for me - no, scan it please", [("copy", "document", "may", "may")]),
        ("scan my file - sorry, I mean print it", [("print", "file", "may", "may")]),
    ],
)
def test_the_operation_said_last_harbour(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of("harbour", text, "may") == expected


def test_whose_it_is_still_corrects_the_owner() -> None:
    text = "bring me Wang's stapler - no wait, it's Gao's, bring me that one"
    assert tasks_of("default", text, "zhang") == [("transfer", "stapler", "gao", "zhang")]
