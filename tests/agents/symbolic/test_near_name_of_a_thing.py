"""A thing asked for by a name of several words that is no name of the office's but nearly one
of them, after any typo is mended ("a whitebaord pen" where the whiteboard marker is also called
a board pen; "a whiteboard rubber" for the whiteboard eraser, also a board rubber), is that thing
(blind round 57's class; its offices and sentences were never read): taken where it is anyone's
(a supply), offered by name where it is someone's. A name no thing of the office is near is
still declined."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers import office_builder as ob
from helpers.bursary import bursary, raw_bursary
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(bursary, "ana")
_answered = answered_reader(bursary, "ana")


@pytest.mark.parametrize(
    "text",
    [
        "could some1 bring me a whitebaord pen",
        "bring me a whiteboard pen",
        "can I get a whitebord pen please",
    ],
)
def test_a_near_name_of_a_supply_is_that_supply(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.item, t.recipient) for t in frame.tasks] == [("marker", "ana")], frame


@pytest.mark.parametrize("text", ["bring me a whiteboard rubber", "get me a whitebord rubber"])
def test_a_near_name_of_someones_thing_is_offered_by_its_name(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "whiteboard eraser" in frame.question, frame
    taken = _answered(text, ["yes please"])
    assert [(t.item, t.recipient) for t in taken.tasks] == [("eraser", "ana")], taken


@pytest.mark.parametrize(
    "text", ["bring me a ballpoint pen", "bring me a table lamp", "bring me a tape measure"]
)
def test_a_name_nothing_is_near_is_still_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "there is no" in frame.decline, frame


def test_the_offices_own_name_is_read_as_before() -> None:
    frame = _frame("bring me a whiteboard marker")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("marker", "ana")], frame


@functools.cache
def _two_kits() -> InstructionParser:
    """The bursary with two things of near names: a first aid kit and a first aid bag."""
    raw = raw_bursary()
    raw["item_types"] += [ob.item("kit", "first aid kit"), ob.item("bag", "first aid bag")]
    raw["people"][0]["owns"] += [{"type": "kit"}, {"type": "bag"}]
    return InstructionParser(parse_office(raw, "bursary with two kits"))


@pytest.mark.parametrize("text", ["bring me a first aid case", "bring me a first aid box"])
def test_a_name_near_two_things_asks_which(text: str) -> None:
    frame = _two_kits().parse(text, "ana")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "first aid kit or first aid bag" in frame.question, frame
    taken = _two_kits().parse_with_answers(text, "ana", ["the first aid bag"])
    assert [(t.item, t.recipient) for t in taken.tasks] == [("bag", "ana")], taken
