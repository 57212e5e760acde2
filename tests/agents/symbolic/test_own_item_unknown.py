"""The requester's own thing that the office knows of no such thing of theirs
(``reading.own_item_unknown``): "heat up my lunch please" from someone with no lunch in the
fridge drove the robot and ended "no one could hand over the lunch"; "bring me my book" from
someone who owns no book asked "Who should get your book?". Now said in words and asked where
it is, with no task (nothing moves). Someone who has the thing is served as before, and one
whose thing is on them and asks for it to be brought is asked where it is, never who gets it."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "wang")
_HARBOUR = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "who", "name"),
    [
        ("heat up my lunch please", "wang", "lunch"),  # the class's analogue
        ("bring me my book", "sun", "book"),  # the class's analogue
        ("warm up my leftovers", "sun", "lunch"),
        ("could you fetch my novel", "wang", "book"),
        ("bring me my scissors please", "lee", "scissors"),
    ],
)
def test_a_thing_they_have_none_of_is_asked_where_on_the_default_office(
    text: str, who: str, name: str
) -> None:
    frame = _DEFAULT(text, who)
    assert not frame.tasks, frame
    assert frame.question == (
        f"As far as I know, you have no {name} of your own here. Where is it?"
    ), frame


@pytest.mark.parametrize(
    ("text", "who", "name"),
    [
        ("fetch my lunch for me", "may", "lunch"),  # harbour heats nothing
        ("bring me my umbrella", "will", "umbrella"),
        ("grab me my calculator pls", "may", "calculator"),
    ],
)
def test_a_thing_they_have_none_of_is_asked_where_on_harbour(
    text: str, who: str, name: str
) -> None:
    frame = _HARBOUR(text, who)
    assert not frame.tasks, frame
    assert frame.question == (
        f"As far as I know, you have no {name} of your own here. Where is it?"
    ), frame


@pytest.mark.parametrize(
    ("text", "who", "item"),
    [
        # must not change: they have one (lee's lunch is in the fridge)
        ("heat up my lunch", "lee", "lunch"),
        ("heat up my lunch please", "zhang", "lunch"),
        # a thing of somebody else's, or one of the office's: not the requester's own
        ("bring me a stapler", "sun", "stapler"),
    ],
)
def test_one_they_have_is_served(text: str, who: str, item: str) -> None:
    frame = _DEFAULT(text, who)
    assert frame.question is None, frame
    assert item in [t.item for t in frame.tasks], frame


def test_one_they_have_is_served_on_harbour() -> None:
    frame = _HARBOUR("fetch my lunch for me", "will")
    assert frame.question is None, frame
    assert [t.item for t in frame.tasks] == ["lunch"], frame


@pytest.mark.parametrize(
    ("text", "who", "name"),
    [("bring me my book", "lee", "book"), ("bring me my calculator", "will", "calculator")],
)
def test_one_on_them_brought_to_them_is_asked_where(text: str, who: str, name: str) -> None:
    read = _DEFAULT if who == "lee" else _HARBOUR
    frame = read(text, who)
    assert not frame.tasks, frame
    assert frame.question == f"Where is your {name}? As far as I know you have it with you.", frame
