"""A capitalised word inside a title ("Notices to Mariners", "Code of Practice") that names
nobody in the office is a word of a thing's name, never a colleague to ask about (round
160, class 4; ``reading.title_words``); a colleague after "to" or "for" still receives, and
a name of nobody after a thing of the office ("the Report to Mariners") is still asked."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

from helpers.reading import frame_reader
from helpers.repro_room import repro_room

_repro = frame_reader(repro_room, "bram")


@pytest.mark.parametrize(
    ("office", "requester", "text", "expected"),
    [
        # the class's analogue shapes
        (
            "default",
            "zhou",
            "print the Notices to Mariners file for Wang",
            ("print", "file", "zhou", "wang"),
        ),
        (
            "harbour",
            "may",
            "scan the Notices to Mariners document for Will",
            ("copy", "document", "may", "will"),
        ),
        # variants: other titles, "of" inside them
        (
            "harbour",
            "may",
            "print the Notes to Editors file for Will",
            ("print", "file", "may", "will"),
        ),
        ("harbour", "may", "print the Guide to Procurement file", ("print", "file", "may", "may")),
        (
            "default",
            "zhou",
            "copy the Code of Practice document for Wang",
            ("copy", "document", "zhou", "wang"),
        ),
    ],
)
def test_a_title_word_is_nobody(
    office: str, requester: str, text: str, expected: tuple[str, ...]
) -> None:
    assert tasks_of(office, text, requester) == [expected]


def test_the_colleague_after_a_title_receives() -> None:
    frame = _repro("print the Terms of Reference doc for Ana")
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("print", "bram", "ana")]


@pytest.mark.parametrize(
    ("office", "requester", "text"),
    [
        ("repro", "bram", "give the Report to Mariners"),  # a thing, then "to" someone
        ("repro", "bram", "print my artwork for Mariners"),
        ("harbour", "may", "bring the stapler to Bob"),
    ],
)
def test_a_name_of_nobody_handed_to_is_still_asked(office: str, requester: str, text: str) -> None:
    frame = _repro(text) if office == "repro" else parser(office).parse(text, requester)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "know anyone called" in frame.question
