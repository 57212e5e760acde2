"""A complaint of how a facility or a place feels is a statement (fix154b, class 1): "<the
facility or place>'s (degree word) <adjective, or a participle said as one> (again)" is
answered in words, and nothing moves. A facility's name that opens with its service's verb
("drying room", "binding room") is the clause's subject, never a command to dry or bind
(``reading.place_name_subject``, ``reading.screen.felt_state``)."""

from __future__ import annotations

import pytest
from _offices import parser

from assistantx.core.task_schema import TaskFrame
from helpers.kit_station import kit_station
from helpers.reading import frame_reader

_station = frame_reader(kit_station, "eilidh")


def _told(frame: TaskFrame, said: str) -> None:
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline_outcome == "done", frame
    assert f"Thanks for letting me know {said}." in (frame.decline or ""), frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        # the class's own shape: a facility named after its service (the drying room dries)
        ("drying room's absolutely roasting again", "the drying room is absolutely roasting"),
        # variants: another service's room, an adjective, "is" said whole
        ("binding room's freezing again", "the binding room is freezing"),
        ("binding room is really chilly today", "the binding room is really chilly"),
        ("the packing store's so stuffy today", "the packing store is so stuffy"),
        ("the mess is freezing again", "the mess is freezing"),
    ],
)
def test_a_facility_or_place_that_feels_some_way_is_told(text: str, said: str) -> None:
    _told(_station(text), said)


@pytest.mark.parametrize(
    ("office", "requester", "text", "said"),
    [
        ("default", "zhou", "print room's boiling today", "the print room is boiling"),
        ("default", "zhou", "coffee corner's freezing again", "the coffee corner is freezing"),
        (
            "default",
            "zhou",
            "the meeting room's really stuffy",
            "the meeting room is really stuffy",
        ),
        (
            "harbour",
            "may",
            "copy room's absolutely freezing again",
            "the copy room is absolutely freezing",
        ),
        ("harbour", "may", "supply room's boiling again", "the supply room is boiling"),
        ("harbour", "may", "the kitchen's boiling today", "the kitchen is boiling"),
    ],
)
def test_the_same_on_the_dataset_offices(office: str, requester: str, text: str, said: str) -> None:
    _told(parser(office).parse(text, requester), said)


@pytest.mark.parametrize(
    ("office", "requester", "text"),
    [
        ("default", "zhou", "kitchen's absolutely freezing again"),
        ("default", "zhou", "the printer room's really stuffy today"),
    ],
)
def test_the_class_analogues_move_nothing(office: str, requester: str, text: str) -> None:
    frame = parser(office).parse(text, requester)
    assert frame.tasks == [] and frame.question is None and frame.decline_outcome == "done", frame


# -- must not change: a request after the complaint, the service's own verb, a fault ---------
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("drying room's free now, can you dry my tunic", [("tunic", "dry")]),
        ("binding room's really cold, can you bind my manual", [("manual", "bind")]),
        ("dry my tunic", [("tunic", "dry")]),
    ],
)
def test_a_request_beside_it_is_still_done(text: str, expected: list[tuple[str, str]]) -> None:
    frame = _station(text)
    assert [(t.item, t.operation) for t in frame.tasks] == expected, frame


def test_a_request_after_a_free_kitchen_is_still_done() -> None:
    frame = parser("harbour").parse("kitchen's free now, can you make me a tea", "may")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "tea", "may")]


def test_a_fault_is_still_a_fault() -> None:
    frame = parser("default").parse("the printer's broken", "zhou")
    assert "I can't repair it myself" in (frame.decline or ""), frame
