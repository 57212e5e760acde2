"""A thing told to go onto a place that is no place of the office is asked, also with whom
the favour is for said after it (fix154b, class 2): "chuck my tunic on the pump for me" (the
pump, a fire engine, nothing of the office) is asked where it should go or who should get
it, never moved and never only noted; "for me" places nothing (``screen.placement``)."""

from __future__ import annotations

import pytest
from _offices import parser

from assistantx.core.task_schema import TaskFrame
from helpers.kit_station import kit_station
from helpers.reading import frame_reader

_station = frame_reader(kit_station, "eilidh")


def _asked_where(frame: TaskFrame, said: str) -> None:
    assert frame.tasks == [] and frame.decline is None, frame
    assert (frame.question or "").startswith(f"Sorry, I'm not sure what to do with {said}")
    assert (frame.question or "").endswith("Who should I bring it to?"), frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        # the class's own shape
        ("chuck my tunic on the pump for me", "my tunic (on the pump)"),
        # variants: other verbs, other things, another beneficiary, courtesy after it
        ("stick my coat on the engine for me", "my coat (on the engine)"),
        ("bung my radio on the appliance for me pls", "my radio (on the appliance)"),
        ("chuck my helmet on the pump for Morag", "my helmet (on the pump)"),
        ("put my helmet on the van", "my helmet (on the van)"),
    ],
)
def test_a_place_outside_the_office_is_asked(text: str, said: str) -> None:
    _asked_where(_station(text), said)


@pytest.mark.parametrize(
    ("office", "requester", "text", "said"),
    [
        ("default", "zhou", "stick my cup on the trolley for me", "my cup (on the trolley)"),
        ("default", "zhou", "put my cup on the van", "my cup (on the van)"),
        ("harbour", "may", "stick my calculator on the bus for me", "my calculator (on the bus)"),
    ],
)
def test_the_same_on_the_dataset_offices(office: str, requester: str, text: str, said: str) -> None:
    _asked_where(parser(office).parse(text, requester), said)


@pytest.mark.parametrize(
    ("office", "requester", "text"),
    [
        ("default", "zhou", "stick my coat on the bus for me"),
        ("harbour", "may", "put my helmet on the van"),
    ],
)
def test_a_thing_the_office_does_not_know_is_asked_too(
    office: str, requester: str, text: str
) -> None:
    frame = parser(office).parse(text, requester)
    assert frame.tasks == [] and frame.question is not None, frame


# -- must not change: a service said as where it goes, a place of the office ------------------
def test_on_charge_is_the_service() -> None:
    frame = _station("pop my radio on charge")
    assert [(t.item, t.operation) for t in frame.tasks] == [("radio", "charge")], frame


def test_a_room_of_the_office_is_its_service() -> None:
    frame = _station("chuck my tunic in the drying room for me")
    assert [(t.item, t.operation) for t in frame.tasks] == [("tunic", "dry")], frame


def test_put_the_kettle_on_is_read_as_before() -> None:
    frame = parser("harbour").parse("put the kettle on", "may")
    assert frame.tasks == [] and frame.question == (
        "Sorry, I'm not sure what you need. What should I do, with which item, and for whom?"
    ), frame


# -- a colleague's thing, or any thing put by a verb of placing alone (fix175a, class 2) --------
@pytest.mark.parametrize(
    ("office", "requester", "text", "said"),
    [
        (
            "default",
            "lee",
            "stick Wang's stapler in the snowcat for me",
            "Wang's stapler (in the snowcat)",
        ),
        (
            "default",
            "lee",
            "put Wang's stapler in the snowcat for me",
            "Wang's stapler (in the snowcat)",
        ),
        (
            "default",
            "lee",
            "load Zhang's scissors into the skiff for me",
            "Zhang's scissors (into the skiff)",
        ),
        (
            "default",
            "lee",
            "place Wang's stapler on the trolley for me",
            "Wang's stapler (on the trolley)",
        ),
        (
            "default",
            "lee",
            "stick Wang's stapler in the snowcat for Zhang",
            "Wang's stapler (in the snowcat)",
        ),
        (
            "default",
            "lee",
            "leave Wang's stapler in the snowcat for me",
            "Wang's stapler (in the snowcat)",
        ),
        ("default", "lee", "pop the stapler in the skiff for me", "the stapler (in the skiff)"),
        (
            "harbour",
            "may",
            "stash Bill's ruler inside the dinghy for me",
            "Bill's ruler (inside the dinghy)",
        ),
    ],
)
def test_someone_elses_thing_put_somewhere_unknown_is_asked(
    office: str, requester: str, text: str, said: str
) -> None:
    _asked_where(parser(office).parse(text, requester), said)


@pytest.mark.parametrize(
    ("text", "task"),
    [
        # a verb that also gives, with a thing nobody is named as owning: for the speaker
        ("leave the stapler on the shelf for me", ("transfer", "stapler", None, "lee")),
        # a place of the office: read as before
        ("put Wang's stapler on my desk for me", ("transfer", "stapler", "wang", "lee")),
        ("bring me Wang's stapler", ("transfer", "stapler", "wang", "lee")),
    ],
)
def test_the_neighbours_stay(text: str, task: tuple[str, str, str | None, str]) -> None:
    frame = parser("default").parse(text, "lee")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame
