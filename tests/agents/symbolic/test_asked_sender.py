"""A colleague asked to send a file sends their own ("could Mark send me his file?", "can
Grace forward me her file", "would Hu email me the file?"): a get_file from them to whom the
clause names, never back to them. Whose the file is, said ("my file", "Wang's file"), stays as
said; "could you send Mark my file?" still forwards the requester's own."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import ForwardFile
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "will")
_DEFAULT = frame_reader(default_office, "lee")


def _sends(frame: object) -> list[tuple[str, str | None, str]]:
    tasks = getattr(frame, "tasks", [])
    return sorted((t.kind, t.owner, t.recipient) for t in tasks)


@pytest.mark.parametrize(
    ("text", "sender"),
    [
        ("could Mark send me his file?", "mark"),
        ("can Grace forward me her file", "grace"),
        ("could Ken send me the file", "ken"),
        ("would Dawn forward me her file please", "dawn"),
        ("can Joy email her file to me", "joy"),
        ("ask Rose to email me the file", "rose"),  # already so: the asked one's
    ],
)
def test_harbour_the_asked_colleague_sends_their_file_to_me(text: str, sender: str) -> None:
    assert _sends(_HARBOUR(text)) == [("send_file", sender, "will")], _HARBOUR(text)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("could Zhang send me his file?", [("send_file", "zhang", "lee")]),
        ("can Wang forward me her file", [("send_file", "wang", "lee")]),
        ("could Hu email me the file?", [("send_file", "hu", "lee")]),
        # his is the sender's, not the last colleague named; it goes to Wang
        ("could Zhang send Wang his file?", [("send_file", "zhang", "wang")]),
        ("could Zhang send his file to Wang", [("send_file", "zhang", "wang")]),
    ],
)
def test_default_office_the_asked_colleague_sends_their_file(
    text: str, expected: list[tuple[str, str, str]]
) -> None:
    assert _sends(_DEFAULT(text)) == expected, _DEFAULT(text)


@pytest.mark.parametrize(
    ("reader", "text", "expected"),
    [
        (_HARBOUR, "could you send Mark my file?", [("send_file", "will", "mark")]),
        (_DEFAULT, "could you send Zhang my file?", [("send_file", "lee", "zhang")]),
        (
            _HARBOUR,
            "send my file to Hope and Ray",
            [("send_file", "will", "hope"), ("send_file", "will", "ray")],
        ),
        (_HARBOUR, "Ken, could you send me your file", [("send_file", "ken", "will")]),
    ],
)
def test_must_not_change_the_requesters_own_file_and_a_vocative(
    reader: object, text: str, expected: list[tuple[str, str, str]]
) -> None:
    frame = reader(text)  # type: ignore[operator]
    assert _sends(frame) == expected, frame


async def test_end_to_end_marks_file_reaches_the_requester() -> None:
    run = await run_instruction(harbour_office(), "will", "could Mark send me his file?")
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    sent = [r.action for r in trace.actions() if isinstance(r.action, ForwardFile)]
    assert [(a.source, a.target) for a in sent] == [("mark", "will")], trace.summary
