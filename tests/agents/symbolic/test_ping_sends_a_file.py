""" "Ping" is chat for sending a file ("ping the file to Drew"): blind round 96's "print my half
time stats and ping the file to Drew too", with "ping" unknown, was restated as one print for
Drew and, on the requester's yes, the printout went to Drew. A file pinged is a file sent; to
ping a person ("ping Wang and ask …") is only to message them, never to give them a thing."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "print my file and ping the file to Wang too",
            [("print", "file", "lee", "lee"), ("send_file", "file", "lee", "wang")],
        ),
        ("ping me Wang's file", [("send_file", "file", "wang", "lee")]),
        ("ping my file over to Zhang", [("send_file", "file", "lee", "zhang")]),
        ("can you ping the file to Zhang pls", [("send_file", "file", "lee", "zhang")]),
    ],
)
def test_a_pinged_file_is_sent(text: str, tasks: list[tuple[str, str, str, str]]) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == tasks


def test_pinging_a_person_gives_them_nothing() -> None:
    frame = _default("can you ping Wang and ask if he has a stapler")
    assert all(t.recipient == "lee" for t in frame.tasks), frame
