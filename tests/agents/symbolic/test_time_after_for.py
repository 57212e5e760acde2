"""A time said after "for" is never the thing asked for from a facility
(``reading.unlisted_thing``): "could you get me a couple of cortados for tonight from the
coffee machine" was declined as "there is no tonight at the coffee machine". The word before
"for <time>" names the thing: a variety of the facility's one product is read as that
product ("a flat white for tomorrow from the coffee machine": coffee), and a thing it does
not make is declined by its own name, never by the time's. On the dataset's default office
and harbour."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "pat")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


@pytest.mark.parametrize(
    ("office", "text", "item"),
    [
        # the class's analogues, said with a variety of the product
        ("default", "could you get me a flat white for tomorrow from the coffee machine", "coffee"),
        ("default", "a flat white for tonight from the coffee machine please", "coffee"),
        # variants of our own
        (
            "default",
            "get me a couple of chocolate bars for later on from the vending machine",
            "snack",
        ),
        ("harbour", "could you get me a green tea for this afternoon from the kettle", "tea"),
        # must not change: no time said
        ("default", "get me a snack from the vending machine", "snack"),
    ],
)
def test_the_thing_before_a_time_is_what_is_asked(office: str, text: str, item: str) -> None:
    frame = _read(office, text)
    assert frame.decline is None, frame.decline
    assert [t.item for t in frame.tasks] == [item], (frame.tasks, frame.question)


@pytest.mark.parametrize(
    ("office", "text", "thing"),
    [
        (
            "default",
            "could you get me a couple of cortados for tonight from the coffee machine",
            "cortados",
        ),
        ("default", "a cortado for later on from the coffee machine please", "cortado"),
        ("harbour", "get me some chloroform for tomorrow from the kettle", "chloroform"),
    ],
)
def test_a_thing_not_made_is_declined_by_its_own_name(office: str, text: str, thing: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], frame.tasks
    assert frame.decline is not None and f"there is no {thing} at" in frame.decline, frame.decline
