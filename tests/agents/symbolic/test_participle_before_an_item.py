"""A past participle between "my"/"the" and an item says the state the item is already in,
not a request (blind rounds 61-62's class: "send my signed <paper> by courier to ..." was
asked "Which item do you mean to be signed?" and failed): the request is the clause's own verb
said before it (courier, bring, send), also where the participle is an office service's
("printed", "couriered") or the paper is said in an everyday noun the office does not list
("my signed letter"). After the item ("get my contract signed by Dr Lee", "have it
couriered") the participle is still the work asked for (``helpers.courier_room``)."""

from __future__ import annotations

import pytest

from helpers.courier_room import courier_room
from helpers.reading import frame_reader

_frame = frame_reader(courier_room, "bjorn")


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("send my signed statement by courier to Crown Court", "Crown Court"),
        ("courier my signed letter to Crown Court", "Crown Court"),
        ("courier my signed contract to the head office", "the head office"),
        ("courier my printed contract to the head office", "the head office"),
        ("courier my stamped form to Acme Ltd", "Acme Ltd"),
        ("please dispatch my sealed letter to Acme Ltd", "Acme Ltd"),
        ("could you courier the signed contract to Crown Court for me", "Crown Court"),
    ],
)
def test_the_send_out_is_asked_for_the_item_as_it_is(text: str, place: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.operation, t.item, t.owner, t.destination) for t in frame.tasks] == [
        ("heat", "courier", "document", "bjorn", place)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring Ana my signed letter",
        "bring Ana my printed contract",
        "bring Ana my couriered contract",
        "take my stamped statement to Ana",
    ],
)
def test_a_handing_on_is_asked_for_the_item_as_it_is(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("transfer", "document", "bjorn", "ana", None)
    ], frame


@pytest.mark.parametrize(
    ("with_participle", "without"),
    [
        ("bring me my couriered contract", "bring me my contract"),
        ("bring me the stamped contract", "bring me the contract"),
        ("please bring me my sealed contract", "please bring me my contract"),
    ],
)
def test_the_participle_changes_nothing_of_the_reading(with_participle: str, without: str) -> None:
    assert _frame(with_participle).model_dump(exclude={"evidence"}) == _frame(without).model_dump(
        exclude={"evidence"}
    )


@pytest.mark.parametrize(
    ("text", "kind", "operation"),
    [
        ("get my contract signed by Dr Lee", "sign", None),
        ("get my letter signed by Dr Lee", "sign", None),
        ("get my contract couriered to Acme Ltd", "heat", "courier"),
        ("could you have my statement couriered to Acme Ltd?", "heat", "courier"),
        ("print my contract and courier it to Acme Ltd", "copy", "print"),
    ],
)
def test_the_work_asked_after_the_item_is_still_asked(
    text: str, kind: str, operation: str | None
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.operation) for t in frame.tasks][:1] == [(kind, operation)], frame
