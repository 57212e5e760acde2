"""A question about a thing at a place ("any wipes in the kitchenette?") is answered about
what the office keeps there (a facility's supplies or products there, an owner's thing kept
there), not only with who has one elsewhere (``reading.screen.kept_at_place``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("read", "text", "said"),
    [
        # the class's analogue: nothing kept there, said; who has some follows
        (
            "default",
            "any wipes in the kitchenette?",
            "I don't know of any wipes kept in the Kitchenette. As far as I know, Yang Lei and "
            "Lin Tao have some wipes.",
        ),
        ("default", "got any wipes at desk 11?", "Lin Tao keeps some wipes at Desk 11."),
        (
            "default",
            "is there a stapler in the kitchenette?",
            "I don't know of a stapler kept in the Kitchenette.",
        ),
        (
            "harbour",
            "any label makers in the supply room?",
            "May Okafor keeps a label maker in the Supply room.",
        ),
        (
            "harbour",
            "any notepads in the supply room?",
            "The stationery cupboard in the Supply room makes them.",
        ),
        ("harbour", "any highlighters in the kitchen?", "I don't know of a highlighter kept"),
    ],
)
def test_a_place_asked_is_answered_about_the_place(read: str, text: str, said: str) -> None:
    frame = {"default": _default, "harbour": _harbour}[read](text)
    assert frame.tasks == [], frame
    assert said in (frame.question or ""), frame.question


def test_must_not_change_without_a_place() -> None:
    question = _default("any wipes?").question or ""
    assert question == (
        "As far as I know, Yang Lei and Lin Tao have some wipes. Shall I bring you some?"
    )


def test_must_not_change_a_facility_is_asked_about_itself() -> None:
    # "in the fridge": the facility's own answer, as before
    assert "is in service" in (_default("any wipes in the fridge?").decline or "")


@pytest.mark.parametrize(
    "text",
    [
        "Zhang needs a stapler at desk 4, could you take him one",
        "Zhang needs a stapler at Desk 4 - can you bring him one",
    ],
)
def test_a_colleagues_need_at_their_own_place_is_another_one_brought_there(text: str) -> None:
    # Zhang sits at desk 4 with his own stapler: "a stapler at desk 4" is where he needs
    # one, not his own there (it was "Zhang Wei already has their stapler; who should get it?")
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", None, "zhang")]


@pytest.mark.parametrize("text", ["I need a stapler from desk 4", "I need the stapler at desk 4"])
def test_a_thing_from_a_colleagues_place_for_the_requester_is_theirs(text: str) -> None:
    # must not change: taken from desk 4 for the requester, it is the one there, Zhang's
    frame = _default(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "zhang", "lee")]
