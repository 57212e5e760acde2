"""A stamping tool asked for, with the speaker's things to use it on said beside it ("Siobhan's
stamp please, I've a batch of requisitions to stamp"), is the tool lent to the speaker (blind
rounds 61-62's class: the requester's own document was stamped and the stamp never handed
over). The things to stamp say what the tool is for; they ask for no stamping. A paper to be
stamped with a colleague's tool ("get my letters stamped with Siobhan's stamp"), or the work
asked of the robot, is the sealing service as before (``helpers.courier_room``)."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.courier_room import courier_room
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import frame_reader

_frame = frame_reader(courier_room, "bjorn")


@functools.cache
def _default() -> Office:
    return load_office(DEFAULT_FILE)


_default_frame = frame_reader(_default, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "Siobhan's stamp please, I've a batch of requisitions to stamp",
        "Siobhan's stamp please, I have a stack of letters to stamp",
        "could I borrow Siobhan's stamp? I've got a pile of forms to stamp",
        "can I have Siobhan's stamp, loads of letters to stamp",
        "Siobhan's stamp please, got a pile of letters to stamp",
        "Siobhan's stamp please",
    ],
)
def test_the_stamp_is_lent_to_the_speaker(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "office_stamp", "siobhan", "bjorn")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Mao's seal please, I've got a pile of letters to seal",
        "could I borrow Mao's seal? I have a stack of contracts to seal",
    ],
)
def test_the_seal_is_lent_in_the_default_office(text: str) -> None:
    frame = _default_frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "seal", "mao", "lee")
    ], frame


def test_another_tool_asked_for_is_lent_as_before() -> None:
    frame = _frame("can I have Ana's hole punch, loads of sheets to punch")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "hole_punch", "ana")]


@pytest.mark.parametrize(
    "text",
    [
        "get my letters stamped with Siobhan's stamp",
        "stamp my form with Siobhan's stamp",
        "can you stamp my letters with Siobhan's stamp",
    ],
)
def test_a_paper_stamped_with_the_tool_is_the_sealing_service(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks] == [
        ("seal", "document", "bjorn", "siobhan")
    ], frame
