"""A noun before a head noun that the office reads as one of its types ("reader" of "card
reader" and "sd reader") says another kind of the thing where none of the type's own names
puts it there: "a microfiche reader" is no card reader (round 245 handed a colleague's card
reader over, a wrong physical action); it is declined as a thing the office does not have.
An adjective ("the new reader"), a word of the type's names ("the sd reader"), a possessive
and the bare head read as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _desk() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Picture desk",
            [
                ob.person("frank", "Frank Doyle", aliases=["Frank"]),
                ob.person("zoe", "Zoë Castellanos", "card_reader", aliases=["Zoë"]),
            ],
            rooms=[ob.room("desk", "Picture desk", 20.0, 6.0)],
            item_types=[
                ob.item("card_reader", "card reader", synonyms=["sd reader", "memory card reader"]),
            ],
            operations=[],
            facilities=[],
            home="desk",
        )
    )()


_frame = frame_reader(_desk, "frank")


@pytest.mark.parametrize(
    "text",
    [
        "Can you bring me a microfiche reader? Need to check the 1962 editions.",
        "bring me a barcode reader pls",
    ],
)
def test_another_kind_is_declined(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks, frame
    assert frame.decline is not None and "reader" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("can you bring me a reader", None),
        ("can you bring me the new reader", None),
        ("can you bring me an sd reader", None),
        ("bring me Zoë's reader", "zoe"),
    ],
)
def test_the_types_own_reads_as_before(text: str, owner: str | None) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner) for t in frame.tasks] == [("card_reader", owner)], frame
