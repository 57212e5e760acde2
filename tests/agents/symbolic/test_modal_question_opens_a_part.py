"""A question asked of a colleague's work opens a part of its own (fix139c, class 3): "print
my deck, and can drew sign my booking form while ur at it" asked "Who should I pass your file
on to?". After "and" or a comma, a modal of asking, a person and the bare verb of their work
("can Mark sign ...", "could may sign ...") is a request of its own, as "ask Mark to sign"
is (``directed_work.asks_someone_to_work``): the first part stays a print for the requester,
whatever the file is called, and the name may be written lower case though it is also a
word ("mark", "may", "will"); "while ur at it" is filler. A verb that is no colleague's
("and mark them as done") and a single part are read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "grace")


def _tasks(read: ReadFrame, text: str) -> list[tuple[str, str | None, str, str | None]]:
    frame = read(text)
    assert frame.question is None and frame.decline is None, (text, frame.question)
    return [(t.kind, t.item, t.recipient, t.actor) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "signer"),
    [
        ("print my slides, and can mark sign my form while ur at it", "mark"),
        ("print my deck, and can Mark sign my document", "mark"),
        ("print my slides, and could may sign my document while you're at it", "may"),
        ("print my deck, and can will sign my document while ur at it", "will"),
    ],
)
def test_a_print_and_a_colleagues_signature(text: str, signer: str) -> None:
    assert _tasks(_harbour, text) == [
        ("print", "file", "grace", None),
        ("sign", "document", "grace", signer),
    ]


@pytest.mark.parametrize(
    ("text", "first", "work", "doer"),
    [
        ("copy my report, and could wang sign my document while you're at it", "copy", "sign",
         "wang"),
        ("print my file, and can zhang sign my document while ur at it", "print", "sign",
         "zhang"),
        ("print my slides, and could Wang seal my document while you're at it", "print", "seal",
         "wang"),
    ],
)  # fmt: skip
def test_the_same_in_the_default_office(text: str, first: str, work: str, doer: str) -> None:
    tasks = _tasks(_default, text)
    assert [(t[0], t[2], t[3]) for t in tasks] == [(first, "lee", None), (work, "lee", doer)]


@pytest.mark.parametrize(
    "text", ["print my slides and mark them as done", "print my deck", "print my slides"]
)
def test_must_not_change_no_colleague_asked(text: str) -> None:
    assert _tasks(_harbour, text) == [("print", "file", "grace", None)]


def test_must_not_change_the_robot_asked_in_the_second_part() -> None:
    assert _tasks(_harbour, "print my slides, and can you bring me a ruler") == [
        ("print", "file", "grace", None),
        ("transfer", "ruler", "grace", None),
    ]
