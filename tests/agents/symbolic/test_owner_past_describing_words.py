"""A possessive owns the thing past the words that describe it (``reading.possessed_thing``):
"courier Kit's signed statement to Leeds", "bring me Kit's blue stapler". A describing word
between the owner and the thing hid the thing, so an owner nobody in the office is called
was not asked about and the requester's own thing (or anyone's) was sent or fetched instead.
Now the reader asks who is meant; the requester's own thing and a colleague's read as
before, and a describing word with no possessive still fetches any such thing."""

from __future__ import annotations

import pytest

from helpers.chambers_post import chambers_post
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_chambers = frame_reader(chambers_post, "nadia")
_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "may")


def _asks_about(frame: object, name: str) -> None:
    assert frame.tasks == [], frame  # type: ignore[attr-defined]
    question = frame.question  # type: ignore[attr-defined]
    assert question is not None and f"anyone called {name!r}" in question, frame


@pytest.mark.parametrize(
    ("text", "name"),
    [
        ("courier Kit's signed statement to Leeds", "Kit"),
        ("send Kit's signed statement to Leeds by courier", "Kit"),
        ("dispatch Kit's signed brief to the Crown Court", "Kit"),
        ("post Dana's sealed letter to Cardiff", "Dana"),
    ],
)
def test_chambers_asks_about_an_unknown_owner(text: str, name: str) -> None:
    _asks_about(_chambers(text), name)


@pytest.mark.parametrize(
    ("text", "name"),
    [
        ("bring me Kit's blue stapler", "Kit"),
        ("bring me Kit's old stapler", "Kit"),
        ("bring me Kit's signed report", "Kit"),
        ("print Kit's signed report", "Kit"),
    ],
)
def test_default_office_asks_about_an_unknown_owner(text: str, name: str) -> None:
    _asks_about(_default(text), name)


@pytest.mark.parametrize(
    "text",
    ["bring me Kit's wooden ruler", "bring me Kit's broken ruler", "scan Kit's signed contract"],
)
def test_harbour_asks_about_an_unknown_owner(text: str) -> None:
    _asks_about(_harbour(text), "Kit")


# -- neighbours: the requester's own thing, a colleague's, and no owner at all -------------


def test_own_signed_statement_is_still_couriered() -> None:
    frame = _chambers("courier my signed statement to Leeds")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.operation, t.destination) for t in frame.tasks] == [
        ("brief", "nadia", "courier", "Leeds")
    ]


def test_a_colleagues_signed_statement_is_theirs() -> None:
    frame = _chambers("courier Owen's signed statement to Leeds")
    assert [(t.item, t.owner, t.operation) for t in frame.tasks] == [("brief", "owen", "courier")]


def test_a_colleagues_described_ruler_is_theirs() -> None:
    frame = _harbour("bring me Pat's wooden ruler")
    assert [(t.item, t.owner) for t in frame.tasks] == [("ruler", "pat")]


def test_a_described_thing_with_no_owner_is_any_such_thing() -> None:
    frame = _default("bring me the blue stapler")
    assert frame.question is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")]
