"""A carrying errand across the office is a delivery, and "them" can be the desk named before
it (blind round 16's class 2; the round's office and sentences were never read). "standards
need to see my proof ... can you run it over to them and bring it back" takes the proof to the
standards desk for its read and back to the requester: "run" (a verb the courier lists) leads
an errand there, and is never a send-out; "them" is the one desk named before, where no
colleague was. A real courier request still sends out; "them" after people named is asked."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Inquire
from assistantx.core.task_schema import TaskFrame
from helpers.gazette import newsroom
from helpers.reading import answered_reader

_frame = answered_reader(newsroom, "ines")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient, t.operation, t.destination) for t in frame.tasks]


_VETTED = [("heat", "page_proof", "ines", "vet", None)]


@pytest.mark.parametrize(
    "text",
    [
        "standards need to see my proof before it goes. can you run it over to them and bring "
        "it back to me",
        "the standards team need to see my proof. can you run it over to them and bring it back",
        "compliance want to see my page proof. can you pop it over to them and bring it back",
        "compliance want to see my proof. can you take it over to them",
        "standards need to see my proof. can you take it to them",
        "can you run my proof over to the standards desk and bring it back to me",
        "can you run my proof over to the standards desk",
        "nip my proof across to compliance and bring it back please",
        # a desk named by an adjective ("editorial") as the subject
        "editorial need to see my proof before it goes. can you run it over to them and bring "
        "it back to me",
    ],
)
def test_an_errand_to_the_desk_is_its_service_and_back(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None
    assert _tasks(frame) == _VETTED


@pytest.mark.parametrize(
    "text",
    ["run my proof over to Will", "nip my proof across to Will", "pop my proof round to Will"],
)
def test_an_errand_to_a_colleague_is_a_hand_over(text: str) -> None:
    assert _tasks(_frame(text)) == [("transfer", "page_proof", "will", None, None)]


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("courier my proof to the printers in Leeds", "the printers in Leeds"),
        ("can you run my proof to the printers in Leeds", "the printers in Leeds"),
        ("dispatch my proof to Harlow Press", "Harlow Press"),
        # the destination ends where the request's next clause begins, never a firm's "and"
        ("courier my proof to Harlow Press and let me know when it's gone", "Harlow Press"),
        ("dispatch my proof to Smith and Sons", "Smith and Sons"),
        ("dispatch my proof to Procter and Gamble", "Procter and Gamble"),
    ],
)
def test_a_courier_request_still_sends_out(text: str, where: str) -> None:
    assert _tasks(_frame(text)) == [("heat", "page_proof", "ines", "courier", where)]


def test_a_request_after_the_destination_is_its_own_task() -> None:
    frame = _frame("courier my proof to Harlow Press and then bring me the camera")
    assert _tasks(frame) == [
        ("heat", "page_proof", "ines", "courier", "Harlow Press"),
        ("transfer", "camera", "ines", None, None),
    ]


@pytest.mark.parametrize(
    "text",
    [
        # "them" after colleagues were named: whom is asked, never guessed as the desk
        "standards need to see my proof. Will and Mark are there. take it to them",
        # a courier to a desk of the office is no send-out: where outside is asked
        "standards need to see my proof. can you courier it to them",
        # "run it over to" with no item named: what is asked
        "run it over to Will",
    ],
)
def test_unclear_errands_are_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None
    assert "them is here" not in frame.question


@pytest.mark.parametrize(
    "text",
    [
        "did you run my proof over to standards?",
        "thanks for running my proof over to standards",
        "don't run my proof over to standards",
    ],
)
def test_no_request_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


async def test_a_run_has_the_desk_read_it_and_gives_it_back() -> None:
    run = await run_instruction(
        newsroom(),
        "ines",
        "standards need to see my proof before it goes. can you run it over to them and bring "
        "it back to me",
    )
    acted = [r.action for r in run.stm.trace.actions() if not r.refused]
    asked = [a.question for a in acted if isinstance(a, Inquire)]
    # the desk's guard is asked in words a colleague reads: its verb, not "standards read"
    assert asked and all("could you vet" in q for q in asked)
    assert run.stm.trace.outcome == "done"
    assert not run.sim.world.sent_out()
    assert run.sim.world.heated == {"page_proof:ines"}
    assert run.sim.world.holder["page_proof:ines"] == "ines"
