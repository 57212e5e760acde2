"""Blind rounds 20 to 22, classes 2 and 4 (their outsider clause): a clause of its own that
says what a colleague will do with the thing ("take it to Tobin, he wants to show it to the
guest") or that the speaker needs it for someone outside ("photocopy my contract pls, need
one for the client") names no recipient: the thing goes where the request says, nothing to
the outsider, and nothing is asked. A request to hand it to the outsider is still asked about.
On sentences of our own against a kitchen, and the default office."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import load_office
from helpers.airside_kitchen import airside_kitchen
from helpers.reading import frame_reader

_frame = frame_reader(airside_kitchen, "odile")

Row = tuple[str, str | None, str | None, str | None, str]
_OUTSIDER_ASKED = "I hand things only to people of this office"


def _tasks(text: str) -> list[Row]:
    return [(t.kind, t.operation, t.item, t.owner, t.recipient) for t in _frame(text).tasks]


_DISC_TO_TOBIN = ("print", "burn", "doc_file", "odile", "tobin")
_COPY_TO_ME = ("copy", None, "contract", "odile", "odile")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "burn my file onto a disc and take it to Tobin, he wants to show it to the guest",
            [_DISC_TO_TOBIN],
        ),
        (
            "burn my file onto a disc and take it to Tobin. He's showing it to the guest",
            [_DISC_TO_TOBIN],
        ),
        ("photocopy my contract pls, need one for the client", [_COPY_TO_ME]),
        ("photocopy my contract, I need one for the client", [_COPY_TO_ME]),
    ],
)
def test_an_outsider_in_anothers_clause_is_no_recipient(text: str, expected: list[Row]) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert _tasks(text) == expected


def test_an_outsider_the_request_hands_to_is_still_asked() -> None:
    frame = _frame("take my file to Tobin. I need you to give it to the guest")
    assert frame.tasks == [] and frame.question is not None
    assert frame.question.startswith(_OUTSIDER_ASKED)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("photocopy my contract for the client", [_COPY_TO_ME]),
        (
            "burn my file onto a disc for the guest",
            [("print", "burn", "doc_file", "odile", "odile")],
        ),
    ],
)
def test_a_service_on_my_own_thing_for_an_outsider_comes_to_me(
    text: str, expected: list[Row]
) -> None:
    # fixer 93d, class 3 (screen.own_serviced): "for the client" says whom the copy is for;
    # the copy comes back to the requester, who passes it on (was asked about before)
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert _tasks(text) == expected


def test_a_colleague_who_wants_it_for_an_outsider_is_its_recipient() -> None:
    # fixer 93d, class 2 (screen.colleague_need): Tobin wants it, so it would go to Tobin;
    # told, not asked, so confirmed first (was asked about as the guest's before)
    frame = _frame("Tobin wants a disc of my file for the guest")
    assert frame.tasks == [] and frame.question is not None
    assert "Tobin" in frame.question and not frame.question.startswith(_OUTSIDER_ASKED)


@pytest.mark.parametrize(
    "text",
    [
        "bring a temporary pass to Tobin, he's taking the guest airside",
        "bring Tobin a temporary pass please, he is taking the contractor airside",
    ],
)
def test_a_pass_for_a_colleague_who_escorts_an_outsider_goes_to_the_colleague(text: str) -> None:
    assert _tasks(text) == [("transfer", None, "airside_pass", None, "tobin")]


def test_a_pass_for_the_outsider_is_still_declined() -> None:
    frame = _frame("bring a temporary pass to the guest, he's with Tobin")
    assert frame.tasks == [] and frame.decline is not None


def test_the_default_office_copies_the_agreement_for_its_owner() -> None:
    frame = InstructionParser(load_office()).parse(
        "photocopy my agreement pls, need one for the client", "mao"
    )
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("copy", "document", "mao", "mao")
    ]


async def test_the_disc_reaches_tobin_and_nobody_else() -> None:
    run = await run_instruction(
        airside_kitchen(),
        "odile",
        "burn my file onto a disc and take it to Tobin, he wants to show it to the guest",
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    collected = [
        r.action.contact  # type: ignore[union-attr]
        for r in run.stm.trace.actions()
        if r.action.type == "send_qr" and r.action.purpose == "collect"  # type: ignore[union-attr]
    ]
    assert collected == ["tobin"]
