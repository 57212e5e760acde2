"""A service on "the X" (no owner said) asked by someone who has no X, where the only Xs are
colleagues' belongings kept at a facility ("could you get the key copied", the keys kept at
the key cutter): whose X is asked, in one short question, never the requester's own put in
(they have none). Before, the kept belongings made it the requester's own key, and the
requester was asked to put it in the locker (fix213a class 4). A requester who owns one gets
theirs worked on; "my key" is the requester's as said."""

from __future__ import annotations

from helpers.office_builder import (
    facility,
    item,
    kept,
    office_file,
    operation,
    parsed,
    person,
    room,
)
from helpers.reading import frame_reader


def _keys_raw() -> dict[str, object]:
    return office_file(
        "Key room",
        [
            person("bo", "Bo", kept("key", at="shed", facility="cutter")),
            person("cy", "Cy", kept("key", at="shed", facility="cutter")),
            person("dee", "Dee"),
            person("eve", "Eve", "stapler"),
        ],
        rooms=[room("shed", "Key shed", 20.0, 10.0), room("dock", "Dock", 1.0, 1.0)],
        item_types=[item("key", "key"), item("stapler", "stapler")],
        operations=[operation("key_copy", "copy", "cut", name="copy a key", input="key")],
        facilities=[
            facility("cutter", "key cutter", at="shed", guards=["eve"], operations=["key_copy"])
        ],
        home="dock",
    )


_read = frame_reader(parsed(_keys_raw), "dee")


def _said(text: str, who: str) -> list[tuple[str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner) for t in _read(text, who).tasks]


def test_whose_kept_key_is_asked_of_one_with_none() -> None:
    frame = _read("could you get the key copied")
    assert frame.tasks == [] and frame.question == "Whose key do you mean?", frame


def test_an_owner_gets_their_own_worked_on() -> None:
    assert _said("could you get the key copied", "bo") == [("heat", "key", "bo")]


def test_my_key_is_as_said() -> None:
    assert _said("get my key copied", "bo") == [("heat", "key", "bo")]


def test_a_named_owner_is_as_said() -> None:
    assert _said("could you get Bo's key copied", "dee") == [("heat", "key", "bo")]


def _cut_keys_raw() -> dict[str, object]:
    """Keys kept by their owners, and a cutter that makes a copy of one (a product: the work
    read as a copy, not a heat; blind round 213, after its fixes)."""
    return office_file(
        "Key desk",
        [person("bo", "Bo", "key"), person("cy", "Cy", "key"), person("dee", "Dee")],
        rooms=[room("shed", "Key shed", 20.0, 10.0), room("dock", "Dock", 1.0, 1.0)],
        item_types=[item("key", "key", "personal"), item("spare_key", "spare key", "product")],
        operations=[
            operation(
                "cut_key",
                "duplicate",
                "copy",
                name="duplicate a key",
                input="key",
                product="spare_key",
            )
        ],
        facilities=[
            facility(
                "cutter",
                "key cutting machine",
                at="shed",
                guards=["cy"],
                operations=["cut_key"],
                products=["spare_key"],
            )
        ],
        home="dock",
    )


_cut = frame_reader(parsed(_cut_keys_raw), "dee")


def test_whose_key_is_asked_where_the_work_makes_a_copy() -> None:
    frame = _cut("could you get the key copied")
    assert frame.tasks == [] and frame.question == "Whose key do you mean?", frame


def test_an_owner_gets_their_own_copied() -> None:
    assert [(t.item, t.owner) for t in _cut("could you get the key copied", "bo").tasks] == [
        ("key", "bo")
    ]
