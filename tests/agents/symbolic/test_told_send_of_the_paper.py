"""A second sentence telling what someone did with the thing asked for ("Could you get Wang's
report file for me? She emailed it to the wrong person.") is its back-story: its past send is
never a send asked for (a paper "emailed" the office cannot make electronic), nor a new task,
nor a new recipient (fix201b class 4: before, the reader asked "I can't emailed a paper
document here. Shall I bring Wang's report to you?", which the requester answers no, and
nothing was done)."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "task"),
    [
        # the class's own shape
        (
            "Could you get Wang's report file for me? She emailed it to the wrong person.",
            ("send_file", "file", "wang", "lee"),
        ),
        (
            "Could you get Wang's report file for me? she sent it to the wrong person",
            ("send_file", "file", "wang", "lee"),
        ),
        (
            "Could you get Wang's report file for me? Zhang forwarded it to the wrong person.",
            ("send_file", "file", "wang", "lee"),
        ),
        (
            "Could you get Wang's report for me? She emailed it to the wrong person.",
            ("transfer", "document", "wang", "lee"),
        ),
        (
            "Could you get Wang's report for me? She misplaced it.",
            ("transfer", "document", "wang", "lee"),
        ),
        # must not change: the request alone
        ("Could you get Wang's report file for me?", ("send_file", "file", "wang", "lee")),
    ],
)
def test_the_told_send_is_the_back_story(text: str, task: tuple[str, ...]) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


def test_a_send_asked_for_is_still_a_send() -> None:
    # must not change: the report asked to be emailed is its owner's file, forwarded
    # (``emailed_paper``: the office keeps electronic files), never back-story
    frame = _lee("could I have Wang's report? just email it to me")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("send_file", "wang", "lee")]
