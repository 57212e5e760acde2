"""A name of several words opening a statement is its subject (fix129d, class 3): "Hye-jin's
cans have packed in. take her mine?" took Hye-jin's headphones to the requester and gave her
the requester's (a swap: a wrong physical action). The hyphen splits "Hye-jin" into two words,
so the statement did not open with a name and was read as a request for her headphones. The
name is read as one word (speech.py ``_one_word_name``): the statement is context, "her" is
the person of the statement and "mine" the requester's thing of the type just named, taken
to her with nothing taken from her. "bring me Hye-jin's cans" still asks for hers, and
"Wang's stapler is broken, bring me his" is read as before."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader


def _raw_studio() -> dict[str, Any]:
    return ob.office_file(
        "listening studio",
        (
            ob.person("hyejin", "Hye-jin Kwon", "headphones", aliases=["Hye-jin"]),
            ob.person("jeanluc", "Jean-Luc Petit", "headphones", "lamp", aliases=["Jean-Luc"]),
            ob.person("tomas", "Tomas Berg", "headphones", "lamp", aliases=["Tomas"]),
        ),
        rooms=[ob.room("store", "Store room", 4.0, 20.0)],
        item_types=[
            ob.item("headphones", "headphones", synonyms=["cans", "earphones"]),
            ob.item("lamp", "lamp"),
        ],
        operations=[],
        facilities=[],
        home="store",
    )


_studio = ob.parsed(_raw_studio)
_tomas = frame_reader(_studio, "tomas")
_zhang = frame_reader(default_office, "zhang")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("Hye-jin's cans have packed in. take her mine?", "headphones", "hyejin"),
        ("Hye-jin's headphones have died, can you bring her mine", "headphones", "hyejin"),
        ("Jean-Luc's lamp packed in. take him mine?", "lamp", "jeanluc"),
        ("Hye-jin Kwon's earphones have given up. take her mine", "headphones", "hyejin"),
    ],
)
def test_mine_goes_to_the_person_of_the_statement(text: str, item: str, recipient: str) -> None:
    frame = _tomas(text)
    assert frame.question is None and frame.decline is None, frame
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, "tomas", recipient)], frame


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("Wang's stapler is broken. take him mine?", "stapler", "wang"),
        ("Lee's pen ran out, can you bring her mine", "pen", "lee"),
        ("Wang Fang's stapler has packed in. take her mine?", "stapler", "wang"),
    ],
)
def test_the_same_in_the_default_office(text: str, item: str, recipient: str) -> None:
    frame = _zhang(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, "zhang", recipient)], frame


def test_the_same_in_harbour() -> None:
    frame = _may("Ray's charger has packed in. take him mine?")
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", "charger", "may", "ray")], frame


def test_asking_for_her_thing_still_asks_for_hers() -> None:
    frame = _tomas("bring me Hye-jin's cans")
    got = [(t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("headphones", "hyejin", "tomas")], frame


def test_his_broken_one_to_me_is_read_as_before() -> None:
    frame = _zhang("Wang's stapler is broken, bring me his")
    assert frame.tasks == [], frame
    assert frame.question is not None and "cut off" in frame.question, frame
