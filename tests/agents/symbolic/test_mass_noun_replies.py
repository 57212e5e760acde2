"""Replies that count an item agree with it: stuff the office marks as such (``mass``) is one
lot, "There is some hand sanitiser", never "There are hand sanitiser"; plural things stay
plural ("There are staples") and a countable thing stays one ("a mug"). On a small stores
office built for it and on harbour."""

from __future__ import annotations

import pytest

from assistantx.core import wording
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader
from helpers.stores_cupboard import stores

_stores = frame_reader(stores, "ada")


@pytest.mark.parametrize(
    ("text", "reply"),
    [
        ("is there any hand sanitiser?", "There is some hand sanitiser in the stores cupboard."),
        ("is there any alcohol gel?", "There is some hand sanitiser in the stores cupboard."),
        ("is there any scrap paper?", "There is some scrap paper in the stores cupboard."),
        ("do we have copier paper?", "There is some copier paper in the stores cupboard."),
    ],
)
def test_stuff_takes_there_is_some(text: str, reply: str) -> None:
    question = _stores(text).question or ""
    assert question.startswith(reply), question
    assert question.endswith("Shall I bring you some?"), question


def test_plural_things_keep_there_are() -> None:
    """Must not change: a plural that is no stuff is counted as several."""
    question = _stores("are there any staples?").question or ""
    assert question.startswith("There are staples in the stores cupboard."), question


@pytest.mark.parametrize(
    ("name", "mass", "there", "be", "one"),
    [
        ("hand sanitiser", True, "There is some hand sanitiser", "is", "some"),
        ("cornflakes", True, "There is some cornflakes", "is", "some"),
        ("staples", False, "There are staples", "are", "some"),
        ("stapler", False, "There is a stapler", "is", "one"),
        ("scissors", False, "There is a pair of scissors", "are", "one"),
        ("glue", False, "There is some glue", "is", "some"),
    ],
)
def test_wording_agrees(name: str, mass: bool, there: str, be: str, one: str) -> None:
    assert wording.there_is(name, mass=mass) == there
    assert wording.is_are(name, mass=mass) == be
    assert wording.some_or_one(name, mass=mass) == one


def test_made_stuff_is_it_made_things_are_them() -> None:
    assert wording.them_or_it("coffee", mass=True) == "it"
    assert wording.them_or_it("glue") == "it"
    assert wording.them_or_it("badges") == "them"
    assert wording.them_or_it("printout") == "them"


def test_harbour_countable_reply_unchanged() -> None:
    """Must not change: harbour's tape dispenser is a thing, offered as one."""
    question = frame_reader(harbour_office, "pat")("is there any tape?").question or ""
    assert question.endswith("Shall I bring you one?"), question
