"""The requester's own file said in an everyday noun the office does not list, with a verb
whose input is a file ("print my concept sheets", "send Cliff my profiler capture"): the
office's electronic file (``reading.own_papers``, ``file_verbs``/``file_nouns``). The same
noun without such a verb, a statement, or a thing that is no file keeps its old reading."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.sound_desk import sound_desk

_frame = frame_reader(sound_desk, "ingrid")


@pytest.mark.parametrize(
    ("text", "kind", "recipient"),
    [
        ("print my concept sheets and bring them to my desk", "print", "ingrid"),
        ("please print my audio cue sheet", "print", "ingrid"),
        ("could you print my guest list", "print", "ingrid"),
        ("send cliff my profiler capture pls", "send_file", "cliff"),
        ("email my profiler capture to Cliff", "send_file", "cliff"),
        ("forward my session recording to Pia", "send_file", "pia"),
    ],
)
def test_a_file_noun_with_a_file_verb_is_the_requesters_file(
    text: str, kind: str, recipient: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks][:1] == [
        (kind, "file", "ingrid", recipient)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring my profiler capture to cliff",
        "send my bike to cliff",
        "my profiler capture is huge",
        "thanks for sending my profiler capture",
    ],
)
def test_without_a_file_verb_or_a_request_nothing_moves(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame


def test_the_offices_own_paper_keeps_its_reading() -> None:
    frame = _frame("bring my permit to Cliff")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("permit", "ingrid", "cliff")
    ], frame
