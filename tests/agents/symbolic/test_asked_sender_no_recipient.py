"""A colleague asked to send a file is no recipient of it: "could Zhang send Wang my file?"
forwards the requester's file to Wang only (the requester's own file needs no colleague to
send it), never to Zhang as well; with nobody else to receive it ("could Zhang email me my
file": the speaker's own file back to the speaker) whom it goes to is asked. Files sent to
several named people ("send my file to Zhang and Wang") and a sender's own file ("could
Zhang send Wang his file?") are read as before."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "owner", "who"),
    [
        ("could Zhang send Wang my file?", "lee", "wang"),
        ("can Chen forward my file to Hu", "lee", "hu"),
        ("would Wang send Zhang Chen's file?", "chen", "zhang"),
    ],
)
def test_default_office_the_file_goes_only_to_whom_it_is_sent(
    text: str, owner: str, who: str
) -> None:
    frame = _DEFAULT(text)
    got = [(t.kind, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("send_file", owner, who)], frame


@pytest.mark.parametrize(
    ("text", "who"),
    [("could Mark send Rose my file?", "rose"), ("can Grace email Will my file please", "will")],
)
def test_harbour_the_file_goes_only_to_whom_it_is_sent(text: str, who: str) -> None:
    frame = _HARBOUR(text)
    assert [(t.owner, t.recipient) for t in frame.tasks] == [("may", who)], frame


def test_with_nobody_else_to_receive_it_whom_is_asked() -> None:
    frame = _DEFAULT("could Zhang email me my file")
    assert not frame.tasks and frame.question, frame


@pytest.mark.parametrize(
    ("text", "got"),
    [
        ("could Zhang send Wang his file?", [("zhang", "wang")]),  # his own, from him
        ("could Zhang send me his file?", [("zhang", "lee")]),
        ("send my file to Zhang and Wang", [("lee", "zhang"), ("lee", "wang")]),
    ],
)
def test_must_not_change_named_recipients_and_a_senders_own_file(
    text: str, got: list[tuple[str, str]]
) -> None:
    frame = _DEFAULT(text)
    assert [(t.owner, t.recipient) for t in frame.tasks] == got, frame


async def test_end_to_end_only_wang_gets_the_file() -> None:
    run = await run_instruction(default_office(), "lee", "could Zhang send Wang my file?")
    trace = run.stm.trace
    sent = [a.action for a in trace.actions() if a.action.type == "forward_file"]
    assert [(s.source, s.target) for s in sent] == [("lee", "wang")], trace.summary
    assert trace.outcome == "done", trace.summary
