"""A possessive pronoun whose person is named only in a piece the screen set aside (blind
round 28's class, on an office no sentence was written for, ``helpers.rota_desk``): "Is Otto
in? I need his ruler, could you fetch it for me" is Otto's ruler, Otto asked as its owner;
on main whom "his" means was asked. With two colleagues named, or none, it is still asked."""

from __future__ import annotations

import pytest

from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.reading import frame_reader
from helpers.rota_desk import rota_desk

_frame = frame_reader(rota_desk, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "Is Otto in? I need his ruler, could you fetch it for me",
        "Is Otto around? I need his ruler, can you get it for me",
        "is Otto about? need his ruler, could you bring it",
    ],
)
def test_his_is_the_one_colleague_asked_about(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "ruler", "otto", "ada")
    ], frame


def test_him_as_receiver_is_the_one_named_and_the_guard_agrees() -> None:
    text = "Is Otto in? take my ruler to him"
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("ruler", "ada", "otto")]
    assert named_recipients(rota_desk(), memory("ada", text)) == {"otto"}


@pytest.mark.parametrize(
    "text",
    ["Are Otto and Bill in? I need his ruler, could you fetch it", "bring me his ruler"],
)
def test_with_two_or_no_colleagues_named_whom_is_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None
    assert "his" in frame.question


@pytest.mark.parametrize(
    "text",
    ["Is Otto in? thanks for his ruler", "Is Otto in? never mind, I don't need his ruler"],
)
def test_no_request_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []
