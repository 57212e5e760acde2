"""A need, then where the thing comes from said as putting it down at the place of the one in
need, is one errand (reading/put_for.py). "Mark needs a ruler, leave mine on his desk" made two
hand-overs to Mark, anyone's ruler and the speaker's: "leave"/"put" are no task words, so the
request ran on in the need's clause and its "mine" was a second ruler. A verb of putting down
that opens the comma's clause and puts its thing at a person's own place starts a request of
its own, and the need gives way to it as it does for "give him mine"."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")
_default_sun = frame_reader(default_office, "sun")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    ("read", "text", "task"),
    [
        (_harbour, "Mark needs a ruler, leave mine on his desk", ("ruler", "rose", "mark")),
        (_harbour, "Mark needs a ruler. leave mine on his desk", ("ruler", "rose", "mark")),
        (
            _harbour,
            "Will could do with a calculator, leave mine on his desk",
            ("calculator", "rose", "will"),
        ),
        (_harbour, "Mark needs a ruler, put mine on his desk please", ("ruler", "rose", "mark")),
        (_default, "Zhang needs a stapler, put mine on her desk", ("stapler", "lee", "zhang")),
        (_default, "Zhang could do with a stapler - give her mine", ("stapler", "lee", "zhang")),
        (_default, "Wang needs scissors, leave mine on her desk", ("scissors", "lee", "wang")),
        # someone else's: their consent is asked as usual when the errand runs
        (_default_sun, "Wang needs scissors; take him Lee's", ("scissors", "lee", "wang")),
        (_default_sun, "Wang needs scissors, leave mine on her desk", ("scissors", "sun", "wang")),
    ],
)
def test_a_need_and_where_it_comes_from_are_one_errand(
    read: ReadFrame, text: str, task: tuple[str, str, str]
) -> None:
    frame = read(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


def test_two_errands_stay_two() -> None:
    # another thing for the one in need: two hand-overs, as before
    two = _default("Zhang needs a stapler, give her my pen")
    assert [(t.item, t.owner, t.recipient) for t in two.tasks] == [
        ("stapler", None, "zhang"),
        ("pen", "lee", "zhang"),
    ]
    # the speaker's own thing put at someone else's place: both asked about, as before
    other = _harbour("Mark needs a ruler, leave mine on Will's desk")
    assert other.tasks == [] and other.question is not None
    assert "Mark Lindqvist" in other.question and "Will Tanaka" in other.question
    # a need and a request of the speaker's own: both kept, asked as before
    mine = _harbour("Mark needs a ruler and bring me a calculator too")
    assert mine.question == (
        "Shall I bring a ruler to Mark Lindqvist and bring a calculator to you?"
    )
