"""Issue #23, fixer fix143b class 3: "can you bring me the thing from the lab" made the lab's
product. "the thing / that thing / the stuff / the whatsit" from a place names no item: what is
meant is asked, naming what that place makes and keeps (``placeholder_thing``), and nothing is
picked; the answer takes the placeholder's place in the request."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.brewhouse import brewhouse
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_OFFICES = {"default": default_office, "harbour": harbour_office, "brewhouse": brewhouse}
_WHO = {"default": "mao", "harbour": "will", "brewhouse": "ines"}


def _read(office: str, text: str) -> TaskFrame:
    return frame_reader(_OFFICES[office], _WHO[office])(text)


@pytest.mark.parametrize(
    ("office", "text", "said", "there"),
    [
        # the class's analogues
        ("brewhouse", "can you bring me the thing from the lab", "the thing", "lab reports"),
        ("default", "can you bring me the thing from the fridge", "the thing", "lunches"),
        ("default", "can you bring me the thing from the vending machine", "the thing",
         "snacks"),
        ("harbour", "grab me that thing from the cupboard", "that thing", "notepads"),
        ("default", "bring me the stuff from the printer", "the stuff", "printouts"),
        # variants of our own: another placeholder, a room, "out of"
        ("harbour", "bring me the whatsit from the kitchen", "the whatsit", "lunches"),
        ("default", "fetch me that thing out of the fridge please", "that thing", "lunches"),
        ("harbour", "could you get me the thingy from the scanner", "the thingy", "scanned"),
    ],
)  # fmt: skip
def test_the_placeholder_is_asked_naming_what_is_there(
    office: str, text: str, said: str, there: str
) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], frame
    assert frame.question is not None and f"“{said}”" in frame.question, frame
    assert there in frame.question, frame


@pytest.mark.parametrize(
    ("office", "text", "answer", "task"),
    [
        ("harbour", "bring me the thing from the fridge", "my lunch",
         ("transfer", "lunch", "will", "will")),
        ("default", "can you bring me the thing from the vending machine", "a snack",
         ("produce", "snack", None, "mao")),
    ],
)  # fmt: skip
def test_the_answer_takes_the_placeholders_place(
    office: str, text: str, answer: str, task: tuple[str, str, str | None, str]
) -> None:
    frame = answered_reader(_OFFICES[office], _WHO[office])(text, [answer])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


@pytest.mark.parametrize(
    ("office", "text", "kind", "item"),
    [
        # neighbours: a thing named, and "something" (any of what the machine makes)
        ("default", "bring me the printout from the printer", "print", "file"),
        ("default", "bring me something from the vending machine", "produce", "snack"),
        # "the thing is, ...": no place, a way of speaking
        ("default", "the thing is, I need a pen", "transfer", "pen"),
    ],
)
def test_a_named_thing_or_something_is_read_as_before(
    office: str, text: str, kind: str, item: str
) -> None:
    frame = _read(office, text)
    assert [(t.kind, t.item) for t in frame.tasks] == [(kind, item)], frame
