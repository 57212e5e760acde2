"""A statement with a verbless tail after it ("it's sunny today so the yard is packed, 23 dogs
in") asks for nothing: the tail names nothing of the office, and a function word of one of
the office's longer names ("in" of a facility called "machine in the laundry") names nothing
alone (``screen.answer.aside``, ``language.is_function_word``); it had asked "What should I
do?". A tail that names a thing of the office is still read."""

from __future__ import annotations

import pytest

from assistantx.core import language
from helpers import office_builder as ob
from helpers.office_builder import Row
from helpers.reading import frame_reader


def _raw() -> Row:
    people = (
        ob.person("tom", "Tom Walker", "muzzle"),
        ob.person("kofi", "Kofi Asante", "muzzle", "lead"),
    )
    return ob.office_file(
        "daycare",
        people,
        rooms=[
            ob.room("laundry", "Laundry", 4.0, 20.0),
            ob.room("yard", "Yard", 20.0, 20.0, kind="room"),
        ],
        item_types=[
            {"id": "muzzle", "name": "muzzle"},
            {"id": "lead", "name": "dog lead", "synonyms": ["lead"]},
            {"id": "towel", "name": "towel"},
        ],
        operations=[ob.operation("wash", "wash", input="towel")],
        facilities=[
            ob.facility(
                "washer",
                "washing machine",
                at="laundry",
                guards=["kofi"],
                operations=["wash"],
                synonyms=["machine in the laundry"],
            )
        ],
        home="yard",
    )


_tom = frame_reader(ob.parsed(_raw), "tom")


@pytest.mark.parametrize(
    "text",
    [
        "it's sunny today so the yard is packed, 23 dogs in",
        "the yard is packed, 23 dogs in",
        "busy morning, the yard is full, 12 in by nine",
    ],
)
def test_a_statement_with_a_verbless_tail_is_words(text: str) -> None:
    frame = _tom(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None, frame


def test_a_tail_naming_a_thing_is_still_read() -> None:
    # must not change: "need a muzzle" after the statement is a request
    frame = _tom("the yard is packed, need a muzzle")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("muzzle", "tom")], frame


@pytest.mark.parametrize(
    ("word", "function"),
    [("in", True), ("the", True), ("of", True), ("up", False), ("dogs", False), ("zhang", False)],
)
def test_function_words(word: str, function: bool) -> None:
    assert language.is_function_word(word) is function
