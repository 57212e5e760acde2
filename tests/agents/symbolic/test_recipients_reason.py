"""Why the colleague a request gives to needs it: "copy my document and give the copy to Wang,
he needs it for his file" is a copy of the speaker's document handed to Wang; before, "his
file" was read as a thing and the reader asked what "the copy" was of (once, whom to pass the
speaker's file on to). "he/she needs it for ..." after a request that names a colleague is
context only; a need of a thing of its own, or a need by a time, are read as before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.recipients_reason import recipients_reason
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader, parser_for

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "mark")


@pytest.mark.parametrize(
    ("text", "kind", "item", "to"),
    [
        (
            "copy my document and give the copy to Wang, he needs it for his file",
            "copy",
            "document",
            "wang",
        ),
        (
            "print my report and bring it to Wang, he needs it for his meeting",
            "print",
            "file",
            "wang",
        ),
        (
            "copy my document and take the copy to Chen, she needs it for her file",
            "copy",
            "document",
            "chen",
        ),
        (
            "print my file and bring it to Zhou, he really needs it for his document",
            "print",
            "file",
            "zhou",
        ),
    ],
)
def test_default_office(text: str, kind: str, item: str, to: str) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (kind, item, "mao", to)
    ]


@pytest.mark.parametrize(
    ("text", "item", "to"),
    [
        ("print my file and take it to Rose, she needs it for her document", "file", "rose"),
        ("print my file and bring it to Jack, he needs it for his badge", "file", "jack"),
        ("print my file and give the printout to June, she needs it for her file", "file", "june"),
    ],
)
def test_harbour(text: str, item: str, to: str) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame.question
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, "mark", to)]


def test_a_request_alone_is_unchanged() -> None:
    frame = _default("copy my document and give the copy to Wang")
    assert frame.question is None, frame.question
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("document", "mao", "wang")]


def test_a_need_of_its_own_is_no_reason() -> None:
    """ "Wang needs his file": his own file is what he needs, said with no request."""
    frame = _default("Wang needs his file")
    assert any(t.item == "file" and t.owner == "wang" for t in frame.tasks) or (
        frame.question is not None
    )


def test_a_need_of_a_thing_of_its_own_after_a_request_is_not_dropped() -> None:
    """ "..., he needs his file": no "it" points back, so his file is no mere reason: the
    reader must not act on the copy alone as if it had not been said."""
    frame = _default("copy my document and give the copy to Wang, he needs his file")
    alone = [("copy", "document", "mao", "wang")]
    said = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert frame.question is not None or said != alone


@pytest.mark.parametrize(
    "text",
    [
        "give the copy of my document to Wang, he needs it by 3",  # when: kept for the plan
        "bring me Wang's stapler, he needs it for his file",  # "he" is the owner, no party
    ],
)
def test_the_rule_leaves_other_needs_alone(text: str) -> None:
    screen = parser_for(default_office).screen
    spoken = screen.verdicts(text, "mao")
    assert all(
        recipients_reason(screen.terms, spoken.msg, p, "mao") is None for p in spoken.msg.pieces
    )
