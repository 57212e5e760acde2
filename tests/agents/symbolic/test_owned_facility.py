"""A facility's name said as someone's belonging (class 72j-1): "take my kettle to Mark, then
fetch me a ruler" (harbour, as will; the kettle is the kitchen's, owned by nobody) made Mark a
tea. "my X" / "Grace's X" where X is a facility is never the facility's service: the phrase is
asked about before anything moves, and the clear part is done after the answer. "make Mark a
tea" and "get Mark a tea from the kettle" say no owner and keep their reading."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_harbour = frame_reader(harbour_office, "will")
_default = frame_reader(default_office, "zhang")


@pytest.mark.parametrize(
    ("text", "phrase"),
    [
        ("take my kettle to Mark, then fetch me a ruler", "my kettle"),
        ("bring Grace's kettle to Rose", "Grace's kettle"),
        ("fetch me a ruler and take my kettle over to Rose", "my kettle"),
    ],
)
def test_a_facility_said_as_a_belonging_is_asked_about(text: str, phrase: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert f"“{phrase}”" in frame.question


@pytest.mark.parametrize(
    ("text", "phrase"),
    [
        ("take my coffee machine to Lee, then bring me a stapler", "my coffee machine"),
        ("take Wang's coffee machine to Lee and bring me scissors", "Wang's coffee machine"),
    ],
)
def test_on_the_default_office_too(text: str, phrase: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert f"“{phrase}”" in frame.question


def test_the_answer_takes_its_place_and_the_clear_part_is_done() -> None:
    read = answered_reader(harbour_office, "will")
    frame = read("take my kettle to Mark, then fetch me a ruler", ["a tea"])
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "tea", "mark"),
        ("transfer", "ruler", "will"),
    ]


@pytest.mark.parametrize(
    "text", ["make Mark a tea", "get Mark a tea from the kettle", "could you brew Mark a tea"]
)
def test_a_service_with_no_owner_of_the_facility_is_read_as_before(text: str) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "tea", "mark")]


def test_an_item_said_as_a_belonging_is_read_as_before() -> None:
    frame = _default("take my stapler to Lee")
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "zhang", "lee")
    ]
