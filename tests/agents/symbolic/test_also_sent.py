"""A paper made from a file, then the file "also" sent on ("print my report and also send it
to Wang", "print my slides and send them to Zhang as well"): the word of addition makes the
second clause an errand of its own, so the printout is the speaker's and the file is passed
on to the one named (``reading.also_sent``). Without it, or with a verb of carrying, the
printout goes to the one named, as before."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("print my report and also email it to Wang", "wang"),
        ("print my report and also send it to Wang", "wang"),
        ("print my slides and send them to Zhou as well", "zhou"),
        ("print my report and send it to Hu too", "hu"),
        ("Print my file, and also send it over to Hu please", "hu"),
    ],
)
def test_the_printout_is_mine_and_the_file_is_sent_default(text: str, to: str) -> None:
    assert tasks_of("default", text, "zhang") == [
        ("print", "file", "zhang", "zhang"),
        ("send_file", "file", "zhang", to),
    ]


@pytest.mark.parametrize(
    "text",
    [
        "print my slides and send them to Mark as well",
        "could you print my document and also send it to Mark",
    ],
)
def test_the_printout_is_mine_and_the_file_is_sent_harbour(text: str) -> None:
    assert tasks_of("harbour", text, "may") == [
        ("print", "file", "may", "may"),
        ("send_file", "file", "may", "mark"),
    ]


@pytest.mark.parametrize(
    "text",
    [
        "print my report and take it to Wang",
        "print my report and send it to Wang",
        "print my report and take it to Wang as well",
    ],
)
def test_one_errand_the_printout_to_the_one_named(text: str) -> None:
    # must not change: no word of addition on "send", or a verb of carrying
    assert tasks_of("default", text, "zhang") == [("print", "file", "zhang", "wang")]
