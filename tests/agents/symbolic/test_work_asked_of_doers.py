"""The people who do a piece of work, said as a plural noun before one of the office's own
verbs of work ("Can the binders repair my book?", "could the technicians fix my book"),
name who does it, not a service of their own: the request is that work on the thing (blind
round 63's class: declined as "binders repair", a service nothing offers). A colleague
asked by name, and a modifier that makes another service ("3D print"), read as before."""

from __future__ import annotations

import pytest

from helpers.mending_room import mending_room
from helpers.reading import frame_reader

_frame = frame_reader(mending_room, "rosa")


@pytest.mark.parametrize(
    "text",
    [
        "The spine on my old psalter has finally gone. Can the binders repair my book?",
        "Can the binders repair my book?",
        "could the technicians fix my book",
        "can the conservators mend my book please",
        "can someone in the bindery mend my book?",
        # a colleague by name who keeps the bench: as before (one who keeps none is asked
        # about first, ``named_doer``: test_named_doer.py)
        "can Nell repair my book",
    ],
)
def test_the_work_is_asked_for(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("book", "rosa", "rosa")]
    assert frame.tasks[0].kind == "heat", frame  # the plain work on the item, as "mend my book"


def test_a_modifier_of_a_service_is_still_another_service() -> None:
    frame = _frame("3D print my file")
    assert frame.decline is not None and "3D print" in frame.decline, frame
