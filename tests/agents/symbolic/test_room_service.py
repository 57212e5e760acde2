"""The requester's own thing taken to a room whose machines work on it ("can you take my wheel
down to wrapping", the wrapping room's wax bath and vacuum packer both working on cheeses):
which service is asked, or the one service is done, the thing back to the requester; never a
transfer of the requester's own thing to the requester, nor who in the room gets it asked
(``reading.room_service``). A room with no such service is asked about as before."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import TaskFrame
from helpers import office_builder as ob
from helpers.dataset_offices import default_office
from helpers.reading import answered_reader, frame_reader

_WAX = ob.operation("wax", "wax", name="wax", input="cheese")
_PACK = ob.operation("vacuum_pack", "vacuum pack", "vac pack", name="vacuum pack", input="cheese")
_BATH = ob.facility("wax_bath", "wax bath", at="wrapping", guards=["bo"], operations=["wax"])
_PACKER = ob.facility(
    "vacuum_packer", "vacuum packer", at="wrapping", guards=["bo"], operations=["vacuum_pack"]
)


def _raw(operations: list[dict[str, Any]], facilities: list[dict[str, Any]]) -> dict[str, Any]:
    return ob.office_file(
        "dairy",
        (
            ob.person("lee", "Lee Ming", "cheese"),
            ob.person("ana", "Ana Ruiz", "cheese"),
            ob.person("bo", "Bo Dahl"),
        ),
        rooms=[
            ob.room("wrapping", "Wrapping room", 4.0, 20.0),
            ob.room("store", "Store room", 14.0, 20.0, kind="room"),
        ],
        item_types=[
            ob.item("cheese", "cheese", "personal", synonyms=["wheel", "cheese wheel"]),
            ob.item("knife", "knife"),
        ],
        operations=operations,
        facilities=facilities,
        everyone_owns=["knife"],
        home="store",
    )


def _two() -> Office:
    return parse_office(_raw([_WAX, _PACK], [_BATH, _PACKER]), "dairy")


def _one() -> Office:
    return parse_office(_raw([_WAX], [_BATH]), "dairy")


_TWO = frame_reader(_two, "lee")
_ONE = frame_reader(_one, "lee")
_TWO_ANSWERED = answered_reader(_two, "lee")
_DEFAULT = frame_reader(default_office, "lee")

_WHICH = "What should I do with your cheese in the Wrapping room: wax it, or vacuum pack it?"


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        # the class's analogue (was who there should get it, or the wheel back to Lee)
        "can you take my wheel down to wrapping",
        "take my cheese to the wrapping room please",
        "could you run my cheese wheel over to the wrapping room",
    ],
)
def test_two_services_there_which_is_asked(text: str) -> None:
    frame = _TWO(text)
    assert frame.question == _WHICH, frame
    assert frame.tasks == []


@pytest.mark.parametrize(
    ("answer", "operation"),
    [
        ("the wax bath one", "wax"),
        ("the vacuum packer", "vacuum_pack"),
        ("the vac pack", "vacuum_pack"),
    ],
)
def test_the_answer_chooses_the_service(answer: str, operation: str) -> None:
    frame = _TWO_ANSWERED("can you take my wheel down to wrapping", [answer])
    assert [(t.operation, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (operation, "cheese", "lee", "lee")
    ], frame


def test_one_service_there_is_done() -> None:
    frame = _ONE("can you take my wheel down to wrapping")
    assert frame.question is None, frame
    assert len(frame.tasks) == 1 and frame.tasks[0].kind != "transfer", frame
    assert _tasks(frame)[0][1:] == ("cheese", "lee", "lee")
    assert frame.tasks[0].operation in (None, "wax")


def test_default_office_the_one_service_of_the_room() -> None:
    # the print room's printer copies papers; the kitchenette's microwave heats lunches
    assert _tasks(_DEFAULT("take my document down to the print room")) == [
        ("copy", "document", "lee", "lee")
    ]
    assert _tasks(_DEFAULT("take my lunch down to the kitchenette")) == [
        ("heat", "lunch", "lee", "lee")
    ]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a colleague said to need it: hers, carried there as before
        ("Ana needs my wheel, take it to wrapping", [("transfer", "cheese", "lee", "ana")]),
        # the service said: as before
        ("wax my wheel", [("heat", "cheese", "lee", "lee")]),
        # to a colleague: as before
        ("take my wheel to Bo", [("transfer", "cheese", "lee", "bo")]),
    ],
)
def test_must_not_change_neighbours(
    text: str, expected: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    frame = _TWO(text)
    assert frame.question is None and _tasks(frame) == expected, frame


@pytest.mark.parametrize(
    "text",
    [
        # a room with no service on cheeses: who there gets it, as before
        "take my wheel to the store room",
        # a colleague's wheel: no service asked of the room for it
        "take Ana's wheel to wrapping",
        # no service there works on a knife
        "take my knife down to wrapping",
    ],
)
def test_must_not_change_who_there_is_asked(text: str) -> None:
    frame = _TWO(text)
    assert frame.tasks == [] and "who there should get it?" in (frame.question or ""), frame
