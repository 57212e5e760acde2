"""A complaint about one's own thing, then chat's laugh, then a question proposing one of the
office's services on "it" ("my badge is peeling lol can it go through the laminator") asks for
that service on the requester's own thing: the laugh ends the complaint as a full stop would
(blind rounds 43-48's class: the whole was one statement, noted and nothing done). The
complaint alone, with its laugh, stays a remark."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.word_names import word_names

_frame = frame_reader(word_names, "petra")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("my crew ID's falling apart lol can it go thru the laminator", "badge"),
        ("my badge is peeling haha could it go through the laminator?", "badge"),
        ("my badge is peeling lmao, could u laminate it", "badge"),
        ("my drafts are confidential lol can they be shredded", "draft"),
        # with a comma, as before
        ("my badge is peeling, could it go through the laminator?", "badge"),
        ("these drafts are confidential, could they be shredded?", "draft"),
    ],
)
def test_the_service_is_asked_for_on_the_requesters_own_thing(text: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, "petra", "petra")], (
        frame
    )
    assert frame.question is None and frame.decline is None, frame


@pytest.mark.parametrize(
    "text",
    ["my badge is peeling lol", "my badge is peeling haha", "my badge is peeling lol."],
)
def test_the_complaint_alone_stays_a_remark(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline_outcome == "done", frame


@pytest.mark.parametrize(
    "text", ["lol can you bring me a mug", "haha ok could you bring me a mug", "bring me a mug lol"]
)
def test_a_laugh_beside_a_plain_request_changes_nothing(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "mug", "petra")], (
        frame
    )
