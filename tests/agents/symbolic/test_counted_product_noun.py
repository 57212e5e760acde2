"""A product called by its own operation's verb, after a word that counts it ("a copy", "two
copies", "another photocopy"), is the thing made, never the verb (``made_objects``): "make me a
copy" asks for a copy of the requester's paper, as "make me a printout" asks for a printout of
their file, and is never answered "there is no copy in this office" where the office copies."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("make me a copy", "wang"),
        ("could you make me two copies", "wang"),
        ("can someone make me a photocopy", "wang"),
        ("could you get Mao to make me a copy", "wang"),
        ("could you get Xu to make me two copies", "wang"),
        ("make a copy for Zhang", "zhang"),
        ("make Gao another copy", "gao"),
        ("make me a copy of it", "wang"),
    ],
)
def test_a_copy_is_a_copy_of_my_paper(text: str, to: str) -> None:
    frame = parser("default").parse(text, "wang")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("copy", "document", "wang", to)
    ], frame
    assert "no copy in this office" not in (frame.decline or "")


def test_whose_paper_after_of_is_kept() -> None:
    assert tasks_of("default", "make me a copy of Zhang's contract", "wang") == [
        ("copy", "document", "zhang", "wang")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "make me a copy",
        "could you get Mark to make me two copies",
    ],
)
def test_a_copy_where_nothing_copies_is_declined(text: str) -> None:
    frame = parser("harbour").parse(text, "may")
    assert frame.tasks == [] and "copies" in (frame.decline or ""), frame


@pytest.mark.parametrize(
    ("office", "text", "who", "tasks"),
    [
        # "the copy" is one someone may hold: not read as a copy to make
        ("default", "bring me the copy", "wang", []),
        # a copy of a thing the office does not know is no copy of the speaker's paper
        ("default", "bring me a copy of the agenda", "wang", []),
        ("default", "copy my document", "wang", [("copy", "document", "wang", "wang")]),
        ("harbour", "can you make me a printout", "may", [("print", "file", "may", "may")]),
    ],
)
def test_must_not_change(
    office: str, text: str, who: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, who) == tasks
