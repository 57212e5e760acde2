"""A colleague who "should get" a thing is its recipient (fix139c, class 1): "Wang should get
a copy of my report" made the copy and handed it to the requester. The name, then "should
get" and the thing, says who is to end up with it (``core.asked_to_have``, the one rule the
reader and the consent guard both read recipients with, so the guard lets that hand-over
go). "should have" says where a thing is believed to be, and "should get me one" has the
colleague get it for the requester: neither names a recipient."""

from __future__ import annotations

import pytest

from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "grace")


@pytest.mark.parametrize(
    ("read", "text", "task"),
    [
        (_default, "Wang should get a copy of my report", ("copy", "wang")),
        (_default, "Wang should get a printout of my file", ("print", "wang")),
        (_harbour, "Hope should get a printout of my rota", ("print", "hope")),
    ],
)
def test_who_should_get_the_thing_receives_it(
    read: ReadFrame, text: str, task: tuple[str, str]
) -> None:
    assert [(t.kind, t.recipient) for t in read(text).tasks] == [task], text


def test_the_guard_reads_the_same_recipient() -> None:
    said = "Wang should get a copy of my report"
    assert named_recipients(default_office(), memory("lee", said)) == {"wang"}
    said = "Hope should get a printout of my rota"
    assert named_recipients(harbour_office(), memory("grace", said)) == {"hope"}


@pytest.mark.parametrize(
    "text",
    [
        "Zhang should have a copy of my file, can you bring it to me",  # where it is
        "Zhang has a copy of my file, can you bring it to me",  # the holder
        "Wang should get me a coffee",  # Wang gets it for me
    ],
)
def test_must_not_change_no_recipient_but_me(text: str) -> None:
    frame = _default(text)
    assert all(t.recipient == "lee" for t in frame.tasks), text
    assert named_recipients(default_office(), memory("lee", text)) == set(), text
