"""A thing put down next to a colleague's own, named by the owner alone, is delivered to that
colleague's place (reading/near_possessive.py). "put the ruler next to Mark's" fetched two
rulers for the speaker, one of them Mark's own: the bare possessive was read as a second
thing asked for. After a verb of putting down, "<next to / beside / by ...> Mark's" is
where the thing goes: Mark's desk, one delivery, and Mark's own ruler never moves. "bring me
the ruler and Mark's" still asks for two. The consent guard reads the place as the reader
does, so the hand-over at Mark's desk is one the guard knows Mark was named for."""

from __future__ import annotations

import pytest

from assistantx.runtime.recipients import _in_roles
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    ("read", "text", "who"),
    [
        (_harbour, "put the ruler next to Mark's", "mark"),
        (_harbour, "put the ruler next to Mark's please", "mark"),
        (_harbour, "leave the calculator beside Will's", "will"),
        (_harbour, "pop my ruler in front of Ray's, thanks", "ray"),
        (_default, "put the book next to Wang's", "wang"),
        (_default, "put my stapler by Zhang's", "zhang"),
        (_default, "put the stapler back next to Wang's", "wang"),
    ],
)
def test_a_thing_put_near_a_colleague_s_own_goes_to_their_place(
    read: ReadFrame, text: str, who: str
) -> None:
    frame = read(text)
    assert len(frame.tasks) == 1, frame
    task = frame.tasks[0]
    assert task.kind == "transfer" and task.recipient == who
    assert task.owner != who  # never the owner's own thing fetched


@pytest.mark.parametrize(
    ("read", "text", "tasks"),
    [
        # two things asked for: unchanged
        (
            _harbour,
            "bring me the ruler and Mark's",
            [("ruler", None, "rose"), ("ruler", "mark", "rose")],
        ),
        # a noun after the possessive: that place, as before
        (_default, "put the book next to Wang's desk", [("book", "lee", "wang")]),
        (_default, "put the book on Wang's desk", [("book", "lee", "wang")]),
        # where it goes said of the person: as before
        (_harbour, "put the ruler next to Mark", [("ruler", None, "mark")]),
    ],
)
def test_two_things_or_a_place_said_in_full_are_read_as_before(
    read: ReadFrame, text: str, tasks: list[tuple[str, str | None, str]]
) -> None:
    frame = read(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == tasks, frame


@pytest.mark.parametrize(
    ("office", "text", "who", "named"),
    [
        (harbour_office, "put the ruler next to Mark's", "rose", {"mark"}),
        (harbour_office, "leave the calculator beside Will's please", "rose", {"will"}),
        (default_office, "put the book next to Wang's", "lee", {"wang"}),
        # a description of which one, or an owner: nobody named to receive it
        (harbour_office, "bring me the ruler next to Mark's", "rose", set()),
        (harbour_office, "bring me the ruler and Mark's", "rose", set()),
    ],
)
def test_the_consent_guard_reads_the_owner_s_place_as_the_reader_does(
    office: OfficeOf, text: str, who: str, named: set[str]
) -> None:
    assert _in_roles(office(), text, who) == named
