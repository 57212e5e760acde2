"""A name + "s" without its apostrophe before words that describe an item and then the
item's word is that name's possessive (``reading.bare_possessives``): "can i get wangs budget
spreadsheet" is Wang's file (it asked which of four people "wangs" meant), "can i get priyas
viability spreadsheet" is Priya's (it was read "get Priya [my] spreadsheet", a file of the
requester's passed on to Priya: a wrong action). "Get Wang his stapler" keeps Wang as the
recipient; a name that itself ends in "s" ("Jules") stays that person."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "may")


def _raw_studio() -> dict[str, Any]:
    return ob.office_file(
        "studio of two names",
        (
            ob.person("priya", "Priya Nair", "stapler"),
            ob.person("jules", "Jules Roy", "stapler"),
            ob.person("jule", "Jule Berg"),
            ob.person("omar", "Omar Haddad"),
        ),
        everyone_owns=["doc_file"],
        rooms=[ob.room("copy_room", "Copy room", 4.0, 20.5)],
        item_types=[
            ob.item("stapler", "stapler"),
            ob.item("doc_file", "document file", "electronic", synonyms=["spreadsheet"]),
        ],
        operations=[],
        facilities=[],
        home="copy_room",
    )


_studio = frame_reader(ob.parsed(_raw_studio), "omar")


def _tasks(frame: Any) -> list[tuple[str, str, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "kind", "item", "owner"),
    [
        ("can i get wangs budget spreadsheet", "send_file", "file", "wang"),
        ("can you send me zhangs quarterly budget spreadsheet", "send_file", "file", "zhang"),
        ("pls forward me suns latest spreadsheet", "send_file", "file", "sun"),
        ("bring me zhangs big red stapler", "transfer", "stapler", "zhang"),
    ],
)
def test_default_office_described_item_is_the_names(
    text: str, kind: str, item: str, owner: str
) -> None:
    frame = _default(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [(kind, item, owner, "lin")], frame


@pytest.mark.parametrize(
    ("text", "kind", "item", "owner"),
    [
        ("could you get me junes yellow highlighter", "transfer", "highlighter", "june"),
        ("can i get rays old umbrella", "transfer", "umbrella", "ray"),
        ("can i get marks budget spreadsheet", "send_file", "file", "mark"),
    ],
)
def test_harbour_described_item_is_the_names(text: str, kind: str, item: str, owner: str) -> None:
    assert _tasks(_harbour(text)) == [(kind, item, owner, "may")]


@pytest.mark.parametrize(
    "text", ["can i get priyas viability spreadsheet", "send me priyas old budget spreadsheet"]
)
def test_the_name_is_the_owner_never_the_recipient(text: str) -> None:
    frame = _studio(text)
    assert _tasks(frame) == [("send_file", "doc_file", "priya", "omar")], frame


def test_a_recipient_before_a_possessive_pronoun_is_unchanged() -> None:
    frame = _default("can you get Wang my stapler")
    assert _tasks(frame) == [("transfer", "stapler", "lin", "wang")], frame
    # "his" is Wang's own: no hand-over to Wang, and not read as anyone's possessive
    his = _default("can you get Wang his stapler")
    assert his.tasks == [] and his.question is not None, his


def test_a_name_that_ends_in_s_is_that_person() -> None:
    frame = _studio("can i borrow jules's stapler")
    assert _tasks(frame) == [("transfer", "stapler", "jules", "omar")], frame
    frame = _studio("can i borrow jules old stapler")
    assert [t.owner for t in frame.tasks] != ["jule"], frame
