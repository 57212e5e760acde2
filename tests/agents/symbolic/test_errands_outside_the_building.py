"""An errand outside the building is declined in words: the robot cannot leave the building
nor buy anything (blind rounds 34-36's class: "pop down to the post office ... and buy a book
of stamps" fetched a colleague's stamp, a coffee from the place across the street was made at
the office's machine). The office's own machine and places, a send-out service's destination
and an outsider's thing named in the office are read as before."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Move
from helpers.notary_office import notary_office
from helpers.reading import frame_reader

_frame = frame_reader(notary_office, "ruth")


@pytest.mark.parametrize(
    "text",
    [
        "can you nip down to the post office on the high street and buy me some stamps",
        "could you pop out to the newsagent and get me a paper",
        "fetch me a latte from the cafe across the road",
        "go buy me a coffee from the Luigi's across the street",
        "drive over to the client's office and collect their signed contract",
        "run to the pharmacy and pick up my prescription",
        "head over to the bank and pay in this cheque",
        "I need you to pop to the bakery for some croissants",
    ],
)
def test_an_errand_outside_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "outside the office" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("get me a coffee from the machine", "produce", "coffee"),
        ("grab me a latte from the machine round the corner", "produce", "coffee"),
        ("bring me a coffee from the kitchen", "produce", "coffee"),
        ("borrow Tomasz's stamp", "transfer", "seal"),
        ("take my letter to Hana in the post room", "transfer", "document"),
    ],
)
def test_the_offices_own_errands_are_read_as_before(text: str, kind: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [(kind, item)], frame


def test_a_send_out_service_to_an_outside_place_is_read_as_before() -> None:
    # a bare "the bank" names no address, asked since fix151b (test_bare_place_asked.py)
    frame = _frame("courier my contract to the Leeds bank")
    assert frame.decline is None, frame
    assert [(t.operation, t.destination) for t in frame.tasks] == [("courier", "the Leeds bank")]


@pytest.mark.parametrize(
    "text",
    [
        "bring me the client's letter",
        "I'm popping to the shop, could you copy my letter",
        "bring me the bank holiday rota",
    ],
)
def test_no_errand_outside_is_read_where_none_is_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None or "outside the office" not in frame.decline, frame


async def test_end_to_end_nothing_moves() -> None:
    text = "can you nip down to the post office and buy me some stamps"
    run = await run_instruction(notary_office(), "ruth", text)
    trace = run.stm.trace
    assert not any(isinstance(r.action, Move) for r in trace.actions()), trace.summary
