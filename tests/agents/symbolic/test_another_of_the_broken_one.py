""" "another one" after a thing of the speaker's said broken means another of that thing, never
an item named in a clause of what the speaker has to do beside it ("I've got a stack of forms
*to sign*", "a cage of notes to *book* out"): reading/screen/statement.py ``stated_items``
(fix61f class 3: "my tracking gun's died and ive got a cage of notes to book out" brought a
coding book). "my pen died, can you get me another one" is read as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")


def _records() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Records library",
            [
                ob.person("soren", "Soren Berg", "scanner_gun", aliases=["Soren"]),
                ob.person("gwen", "Gwen Price", "coding_book", "scanner_gun", aliases=["Gwen"]),
            ],
            rooms=[ob.room("library", "Library", 20.0, 6.0)],
            item_types=[
                ob.item("scanner_gun", "barcode gun", synonyms=["tracking gun"]),
                ob.item("coding_book", "coding manual", synonyms=["book", "coding book"]),
            ],
            operations=[],
            facilities=[],
            home="library",
        )
    )()


_records_frame = frame_reader(_records, "soren")


@pytest.mark.parametrize(
    "text",
    [
        "my pen's died and I've got a stack of forms to sign. can you find me another one",
        "my pen died and I have loads of letters to sign, can you get me another one",
    ],
)
def test_another_one_is_of_the_thing_said_broken(text: str) -> None:
    frame = _default(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [("pen", "lee")], frame


def test_a_word_of_the_office_said_as_the_work_to_do_is_no_thing() -> None:
    frame = _records_frame(
        "my tracking gun's died and ive got a cage of notes to book out. can you find me "
        "another one"
    )
    assert [(t.item, t.recipient) for t in frame.tasks] == [("scanner_gun", "soren")], frame


def test_another_one_of_a_thing_said_alone_is_read_as_before() -> None:
    frame = _default("my pen died, can you get me another one")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("pen", "lee")], frame


def test_the_work_to_do_said_alone_is_still_read() -> None:
    frame = _default("I've got a stack of reports to print, can you bring me some paper")
    assert ("paper", "lee") in [(t.item, t.recipient) for t in frame.tasks], frame
