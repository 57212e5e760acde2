"""Blind round 18, class 4: colleagues who share a first name told apart by an initial ("Jude
A", "Jude C", "Jude O"): the letter "a" after the shared name is the initial, not an article,
where it ends the name ("Jude A's forceps", "to Jude A, she's ..."); before a thing it is still
the article ("give Jude a timer" asks which Jude) (``memory.names.normalize``,
``Lexicon._initial_at``, on ``helpers.histology_lab``; the round's own office and sentences
were never read)."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from assistantx.memory.names import normalize
from helpers.histology_lab import histology_lab
from helpers.reading import frame_reader

_frame = frame_reader(histology_lab, "bea")


def _moves(frame: TaskFrame) -> list[tuple[str | None, str | None, str]]:
    return [(t.item, t.owner, t.recipient) for t in frame.tasks]


def test_an_initial_is_kept_in_a_name_key() -> None:
    assert normalize("Jude A") == "jude a"
    assert normalize("Dr. Jude Ashby") == "jude ashby"


@pytest.mark.parametrize(
    "text",
    [
        "could you grab Jude A's forceps for me?",
        "could you grab jude a's forceps for me?",
        "can you fetch me Jude A's tweezers please",
    ],
)
def test_the_initial_a_names_its_owner(text: str) -> None:
    assert _moves(_frame(text)) == [("forceps", "jude_a", "bea")]


@pytest.mark.parametrize(
    "text",
    [
        "take my timer to Jude A, she's got three incubations going",
        "take my timer to Jude A",
        "take my timer to Jude A please",
    ],
)
def test_the_initial_a_names_the_recipient(text: str) -> None:
    assert _moves(_frame(text)) == [("timer", "bea", "jude_a")]


def test_other_initials_are_unchanged() -> None:
    assert _moves(_frame("could you grab Jude C's forceps for me?")) == [
        ("forceps", "jude_c", "bea")
    ]


@pytest.mark.parametrize("text", ["give Jude a timer", "bring me a timer from Jude"])
def test_an_article_after_the_shared_name_still_asks_which(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None and "Jude Ashby" in frame.question
