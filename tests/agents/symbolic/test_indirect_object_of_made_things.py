"""A made thing for someone named as the indirect object ("make Zhang a copy of my document",
"print Mark a copy of my file", "print Rose my file") goes to that person: the person right
after a giving or making verb, before the thing's noun phrase, is the recipient
(``reading.indirect_object``). Before, a task word after the article ("a *copy*") or a making
verb of the office ("*print* Mark") left the person with no role, and the copy was handed to
the requester. Neighbours keep their reading: "make me a copy of Zhang's document" is Zhang's
paper copied for me, "make a copy of my document for Zhang" was already Zhang's, and "make
Mark print my file" (a bare verb after the person) does not make Mark the recipient."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "wang")
_harbour = frame_reader(harbour_office, "may")


def _read(office: str, text: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = (_default if office == "default" else _harbour)(text)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "task"),
    [
        # the class's analogues
        ("default", "make Zhang a copy of my document", ("copy", "document", "wang", "zhang")),
        ("harbour", "print Mark a copy of my file", ("print", "file", "may", "mark")),
        (
            "default",
            "could you make Zhang two copies of my contract",
            ("copy", "document", "wang", "zhang"),
        ),
        ("default", "get Zhang a coffee", ("produce", "coffee", None, "zhang")),
        # variants with other words, verbs and offices
        ("default", "please make Lin Tao a copy of my report", ("copy", "document", "wang", "lin")),
        ("default", "get Dr Zhang 2 copies of my contract", ("copy", "document", "wang", "zhang")),
        ("default", "print Chen Jie a copy of my file", ("print", "file", "wang", "chen")),
        ("harbour", "print Rose my file", ("print", "file", "may", "rose")),
        ("harbour", "could you print Will two copies of my file", ("print", "file", "may", "will")),
        ("harbour", "scan Grace my document", ("copy", "document", "may", "grace")),
        ("harbour", "brew Grace a tea", ("produce", "tea", None, "grace")),
        ("harbour", "make Pat a printout of my file", ("print", "file", "may", "pat")),
    ],
)
def test_the_indirect_object_receives_the_made_thing(
    office: str, text: str, task: tuple[str, str | None, str | None, str]
) -> None:
    assert _read(office, text) == [task]


@pytest.mark.parametrize(
    ("office", "text", "task"),
    [
        ("default", "Zhang is in the office, make him a copy of my document", "zhang"),
        ("harbour", "Rose asked for my file, print her a copy of it", "rose"),
    ],
)
def test_an_object_pronoun_as_indirect_object_receives(office: str, text: str, task: str) -> None:
    tasks = _read(office, text)
    assert tasks and tasks[-1][3] == task, tasks


@pytest.mark.parametrize(
    ("office", "text", "task"),
    [
        # it is Zhang's paper: copied for me, with his consent
        ("default", "make me a copy of Zhang's document", ("copy", "document", "zhang", "wang")),
        ("harbour", "print me a copy of Mark's file", ("print", "file", "mark", "may")),
        # already right, kept
        ("default", "make a copy of my document for Zhang", ("copy", "document", "wang", "zhang")),
        ("harbour", "print a copy of my file for Mark", ("print", "file", "may", "mark")),
        # a possessive after the verb owns the thing: printed for me
        ("harbour", "print Mark's file", ("print", "file", "mark", "may")),
    ],
)
def test_neighbours_keep_their_reading(
    office: str, text: str, task: tuple[str, str | None, str | None, str]
) -> None:
    assert _read(office, text) == [task]


@pytest.mark.parametrize(
    ("office", "text"),
    [
        ("harbour", "make Mark print my file"),
        ("default", "make Zhang copy my document"),
    ],
)
def test_a_bare_verb_after_the_person_makes_no_recipient(office: str, text: str) -> None:
    # the causative: the person is asked to do it, the result is still the requester's
    tasks = _read(office, text)
    requester = "wang" if office == "default" else "may"
    assert tasks and all(t[3] == requester for t in tasks), tasks


@pytest.mark.parametrize("text", ["print her a copy of my file", "print him my file"])
def test_an_indirect_object_pronoun_with_nobody_named_is_asked(text: str) -> None:
    # never the requester by default: whom "her" means is asked
    frame = _harbour(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Who do you mean" in frame.question, frame
