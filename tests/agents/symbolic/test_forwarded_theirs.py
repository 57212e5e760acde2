"""A colleague's thing said in words the office does not list, asked to be forwarded
(``reading.forwarded_theirs``): "forward me Wang's budget pack and print my own file too" is
Wang's electronic file passed on and the requester's file printed, never the forward dropped
while the print is done. A verb that moves things ("bring", "send" without the speaker after
it) keeps its reading. On the default office and harbour."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "may")

Row = tuple[str, str | None, str | None, str | None]


def _tasks(frame: TaskFrame) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "forward me Wang's budget pack and print my own file too",
            [("send_file", "file", "wang", "lee"), ("print", "file", "lee", "lee")],
        ),
        (
            "send me Zhang's handover notes and print my file",
            [("send_file", "file", "zhang", "lee"), ("print", "file", "lee", "lee")],
        ),
        (
            "ping me Chen's travel plan and bring me a coffee",
            [("send_file", "file", "chen", "lee"), ("produce", "coffee", None, "lee")],
        ),
        ("email me Zhang's handover notes, thanks", [("send_file", "file", "zhang", "lee")]),
        ("could you forward me Wang's budget pack please", [("send_file", "file", "wang", "lee")]),
        ("forward Wang's budget pack to Zhang", [("send_file", "file", "wang", "zhang")]),
    ],
)
def test_default_forwarded_unlisted_thing_is_the_owners_file(text: str, tasks: list[Row]) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == tasks


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "forward me Mark's shipping manifest and print my own file too",
            [("send_file", "file", "mark", "may"), ("print", "file", "may", "may")],
        ),
        (
            "ping me Rose's crew roster and print my file",
            [("send_file", "file", "rose", "may"), ("print", "file", "may", "may")],
        ),
        ("forward Bill's tide tables to Rose", [("send_file", "file", "bill", "rose")]),
    ],
)
def test_harbour_forwarded_unlisted_thing_is_the_owners_file(text: str, tasks: list[Row]) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == tasks


# must not change: the office's own file said by name, a thing the office lists, a verb that
# carries things
def test_named_file_still_both_parts() -> None:
    frame = _default("forward me Wang's file and print my own file too")
    assert _tasks(frame) == [("send_file", "file", "wang", "lee"), ("print", "file", "lee", "lee")]


def test_send_me_a_listed_thing_still_carried() -> None:
    assert _tasks(_default("send me Wang's stapler")) == [("transfer", "stapler", "wang", "lee")]


@pytest.mark.parametrize(
    "text", ["bring me Wang's budget pack", "send Wang's budget pack to Zhang"]
)
def test_a_carrying_verb_is_not_a_forward(text: str) -> None:
    frame = _default(text)
    assert all(t.kind != "send_file" for t in frame.tasks)
    assert frame.question is not None
