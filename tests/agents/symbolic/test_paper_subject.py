"""Fixer fix180c class 2: "I need Zhang's signature on my requisition for the new staplers".
After a work on a paper (sign, stamp, approve, print, copy), "for the (new) <thing>" right after
the paper's phrase says what the paper is about (``paper_subject``), never a second thing:
before, the stapler took the request over ("what do you want me to do with the stapler?")."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "kind", "item", "actor"),
    [
        (
            "I need Zhang's signature on my requisition for the new staplers",
            "sign",
            "document",
            "zhang",
        ),
        ("can Zhang sign my requisition for the staplers", "sign", "document", "zhang"),
        ("can Zhang stamp my order for the new staplers", "seal", "document", "zhang"),
        # must not change: the office's own paper named
        (
            "I need Zhang's signature on my order form for the new staplers",
            "sign",
            "document",
            "zhang",
        ),
    ],
)
def test_the_paper_is_worked_and_its_subject_is_no_thing(
    text: str, kind: str, item: str, actor: str
) -> None:
    frame = _default(text)
    tasks = [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks]
    assert tasks == [(kind, item, "lee", "lee", actor)], frame


def test_a_printed_paper_for_the_new_things_is_the_guessed_file() -> None:
    frame = _default("print my requisition for the new staplers")
    assert frame.question is not None and "print your file" in frame.question, frame


def test_harbour_a_stamped_request_for_new_calculators() -> None:
    frame = _harbour("can Sue sign my purchase requisition for the new calculators")
    assert "calculator" not in (frame.question or ""), frame
    assert all(t.item != "calculator" for t in frame.tasks), frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # must not change: the thing asked for, not after a worked paper
        ("bring me a stapler for my form", [("transfer", "stapler")]),
        ("can you get me a stapler for the new starter", [("transfer", "stapler")]),
        (
            "print my file for the new stapler and bring me a stapler",
            [("print", "file"), ("transfer", "stapler")],
        ),
        ("bring me the new stapler", [("transfer", "stapler")]),
    ],
)
def test_a_thing_asked_for_stays_a_thing(text: str, tasks: list[tuple[str, str]]) -> None:
    frame = _default(text)
    assert [(t.kind, t.item) for t in frame.tasks] == tasks, frame
