"""A definite paper with a modifier the office does not know, worked on for the requester, is
the requester's own when they own one of that type and no other owner is named: "could you
photocopy the expenses document for me?" copies the requester's document. Round 143's class
(an office whose personal paper is a ``form`` called "agreement" too) asked "Whose form do
you mean?"; these pin the reading on the dataset offices and on a small letting office whose
paper type is not called "document"."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_PEOPLE = (
    ob.person("hamish", "Hamish Doyle", "stapler"),
    ob.person("olive", "Olive Brennan"),
    ob.person("pavel", "Pavel Novak", "stapler"),
    ob.person("ruth", "Ruth Okoye"),
)


def _raw_letting_office() -> dict[str, Any]:
    """A letting agency: everyone owns a form (also called an agreement); Ruth's copier
    photocopies one."""
    return ob.office_file(
        "letting agency",
        _PEOPLE,
        everyone_owns=["form"],
        rooms=[ob.room("copy_room", "Copy room", 4.0, 20.5)],
        item_types=[
            ob.item("form", "form", "personal", signable=True, synonyms=["agreement", "paperwork"]),
            ob.item("stapler", "stapler"),
            ob.item("copy", "photocopy", "product", synonyms=["copy", "copies"]),
        ],
        operations=[ob.operation("copy", "copy", "photocopy", input="form", product="copy")],
        facilities=[
            ob.facility(
                "copier",
                "copier",
                at="copy_room",
                guards=["ruth"],
                operations=["copy"],
                products=["copy"],
            )
        ],
        home="copy_room",
    )


letting_office = ob.parsed(_raw_letting_office)

Read = tuple[str, str | None, str | None, str]  # kind, item, owner, recipient


def _tasks(frame: object) -> list[Read]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in getattr(frame, "tasks", [])]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("could you photocopy the expenses document for me?", ("copy", "document", "lin", "lin")),
        ("print the quarterly file for me", ("print", "file", "lin", "lin")),
        ("copy the lease document for me pls", ("copy", "document", "lin", "lin")),
        ("Could you photocopy the deposit agreement for me?", ("copy", "document", "lin", "lin")),
        # the neighbour: another owner named is theirs
        ("copy Wang's expenses document for me", ("copy", "document", "wang", "lin")),
    ],
)
def test_default_office(text: str, task: Read) -> None:
    frame = frame_reader(default_office, "lin")(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [task], frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("could you scan the deposit form for me?", ("copy", "document", "will", "will")),
        ("print the quarterly file for me", ("print", "file", "will", "will")),
        ("scan Mark's expenses document for me", ("copy", "document", "mark", "will")),
    ],
)
def test_harbour(text: str, task: Read) -> None:
    frame = frame_reader(harbour_office, "will")(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [task], frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("Could you photocopy the deposit agreement for me?", ("copy", "form", "hamish", "hamish")),
        ("copy the lease form for me pls", ("copy", "form", "hamish", "hamish")),
        ("photocopy the site paperwork for me", ("copy", "form", "hamish", "hamish")),
        ("could you copy Olive's deposit agreement for me?", ("copy", "form", "olive", "hamish")),
    ],
)
def test_letting_office(text: str, task: Read) -> None:
    frame = frame_reader(letting_office, "hamish")(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [task], frame
