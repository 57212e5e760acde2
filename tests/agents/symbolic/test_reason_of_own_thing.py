"""A reason told of the speaker's own thing by its possessive alone ("could I borrow Ana's
torch? mine wont hold a charge anymore"): "mine" is the subject of a statement, and the
service's word said as a noun in it ("a charge") asks for nothing; the request is the
borrowing (fix213a class 1). Before, the reason was read into the request and the charging
service run on Ana's torch (or declined where the service charges radios only). "could you
charge my torch" and "borrow Ana's torch and charge mine" still ask for the service."""

from __future__ import annotations

import pytest

from helpers.office_builder import facility, item, office_file, operation, parsed, person, room
from helpers.reading import frame_reader


def _camp_raw(charged: str) -> dict[str, object]:
    return office_file(
        "Camp",
        [person("lee", "Lee", "torch"), person("ana", "Ana", "torch"), person("dee", "Dee")],
        rooms=[room("shed", "Charging shed", 20.0, 10.0), room("dock", "Dock", 1.0, 1.0)],
        item_types=[item("torch", "torch"), item("radio", "radio"), item("stapler", "stapler")],
        operations=[operation("charge", "charge", "recharge", name="charge", input=charged)],
        facilities=[
            facility(
                "charger",
                "charging station",
                at="shed",
                guards=["dee"],
                operations=["charge"],
                supplies=["stapler", "radio"],
            )
        ],
        home="dock",
    )


_torches = frame_reader(parsed(lambda: _camp_raw("torch")), "lee")
_radios = frame_reader(parsed(lambda: _camp_raw("radio")), "lee")
_BORROWED = [("transfer", None, "torch", "ana", "lee")]


def _said(frame: object) -> list[tuple[str, str | None, str | None, str | None, str | None]]:
    return [(t.kind, t.operation, t.item, t.owner, t.recipient) for t in frame.tasks]  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    "text",
    [
        "could I borrow Ana's torch? mine wont hold a charge anymore",
        "could I borrow Ana's torch? mine won't hold a charge anymore",
        "could I borrow Ana's torch? mine doesnt hold a charge any more",
    ],
)
@pytest.mark.parametrize("read", [_torches, _radios])
def test_the_reason_of_ones_own_asks_nothing(read: object, text: str) -> None:
    frame = read(text)  # type: ignore[operator]
    assert frame.decline is None and frame.question is None, frame
    assert _said(frame) == _BORROWED, frame


def test_the_service_asked_on_ones_own_is_run() -> None:
    assert _said(_torches("could you charge my torch")) == [("heat", None, "torch", "lee", "lee")]


def test_borrowing_and_the_service_on_mine_are_both_asked() -> None:
    assert _said(_torches("borrow Ana's torch and charge mine")) == [
        *_BORROWED,
        ("heat", None, "torch", "lee", "lee"),
    ]
