"""A polite ask put to anyone at all with "mind" and a gerund ("would someone mind heating up
my lunch", "would anyone mind steaming my waistcoat") asks for the work, as "would you mind
heating ..." does (``reading.joined_gerunds``). Before, "mind heating" was read as a verb
nothing offers and declined ("I can't mind heating", fix213a class 2). "I don't mind
waiting" is still told, "never mind the lunch" still withdraws."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

from helpers.office_builder import facility, item, office_file, operation, parsed, person, room
from helpers.reading import frame_reader

_HEAT = ("heat", "lunch", "lee", "lee")


@pytest.mark.parametrize(
    "text",
    [
        "would someone mind heating up my lunch before the 1pm call? it's gone cold",
        "would anyone mind heating my lunch",
        "Would somebody mind warming up my lunch please",
    ],
)
def test_anyone_minding_the_work_is_asked_it(text: str) -> None:
    assert tasks_of("default", text, "lee") == [_HEAT]


def test_the_joined_gerund_is_a_second_ask() -> None:
    assert tasks_of(
        "default", "would anyone mind heating my lunch and fetching me Wang's stapler", "lee"
    ) == [_HEAT, ("transfer", "stapler", "wang", "lee")]


@pytest.mark.parametrize(
    "text", ["would you mind heating up my lunch", "do you mind heating my lunch"]
)
def test_you_minding_is_read_as_before(text: str) -> None:
    assert tasks_of("default", text, "lee") == [_HEAT]


def test_not_minding_is_told() -> None:
    frame = parser("default").parse("I don't mind waiting", "lee")
    assert frame.tasks == [] and frame.question is None, frame


def test_never_mind_withdraws() -> None:
    frame = parser("default").parse("never mind the lunch", "lee")
    assert frame.tasks == [] and frame.decline is not None and "dropped" in frame.decline, frame


def test_anyone_minding_if_i_borrow_is_a_borrowing() -> None:
    assert tasks_of("default", "would anyone mind if I borrowed Wang's stapler", "lee") == [
        ("transfer", "stapler", "wang", "lee")
    ]


def _tailor_raw() -> dict[str, object]:
    return office_file(
        "Tailor's",
        [person("lee", "Lee", "waistcoat"), person("ana", "Ana", "waistcoat")],
        rooms=[room("press", "Press room", 20.0, 10.0), room("dock", "Dock", 1.0, 1.0)],
        item_types=[item("waistcoat", "waistcoat"), item("stapler", "stapler")],
        operations=[operation("steam", "steam", name="steam", input="waistcoat")],
        facilities=[
            facility(
                "steamer",
                "steamer",
                at="press",
                guards=["ana"],
                operations=["steam"],
                supplies=["stapler"],
            )
        ],
        home="dock",
    )


_read = frame_reader(parsed(_tailor_raw), "lee")


def test_an_office_service_minded_by_anyone_is_asked() -> None:
    """The office's "steam" (a service the task kinds read as heat work), asked of anyone."""
    asked = _read("would someone mind steaming my waistcoat before tonight")
    plain = _read("could you steam my waistcoat")
    assert asked.decline is None and asked.question is None, asked
    said = [(t.kind, t.operation, t.item, t.owner, t.recipient) for t in asked.tasks]
    assert said == [(t.kind, t.operation, t.item, t.owner, t.recipient) for t in plain.tasks]
    assert [(t.item, t.owner) for t in asked.tasks] == [("waistcoat", "lee")], asked
