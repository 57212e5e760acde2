"""A thing named by a colleague's making of it, "the <thing> <Name> did/made/wrote/drew", is
that colleague's ("the slides Zhang did": Zhang's slides), asked of its owner as any
colleague's file or paper is (fix210b class 3: it was read as the requester's own, or whose was
asked). The speaker's own making ("the slides I did") is still the speaker's; another verb
("the report Wang wants") and a verb whose object is someone ("the report Wang made me sign")
say nothing of whose the thing is."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    ("text", "task"),
    [
        (
            "customer at the desk wants to see the slides Zhang did, can u get them to me",
            ("send_file", "file", "zhang", "lee"),
        ),
        ("can you send me the report Wang wrote", ("transfer", "document", "wang", "lee")),
        ("print the slides Zhang did", ("print", "file", "zhang", "lee")),
        ("print the spreadsheet that Sun made last week", ("print", "file", "sun", "lee")),
        ("bring me the contract Zhou drew up", ("transfer", "document", "zhou", "lee")),
        # neighbours already read so
        ("can you send me Wang's report", ("transfer", "document", "wang", "lee")),
        ("print the slides I did", ("print", "file", "lee", "lee")),
    ],
)
def test_the_makers_thing(text: str, task: tuple[str, str, str, str]) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


def test_the_makers_thing_in_harbour() -> None:
    frame = _harbour("print the deck Mark did and bring it to me")
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("print", "mark", "rose")]


@pytest.mark.parametrize(
    "text", ["can you send me the report Wang wants", "bring me the report Wang made me sign"]
)
def test_no_making_says_no_owner(text: str) -> None:
    frame = _default(text)
    assert all(t.owner != "wang" for t in frame.tasks), frame
