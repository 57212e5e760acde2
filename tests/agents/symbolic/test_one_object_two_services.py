"""Two services on one thing in one phrase: "I need this photocopied and signed by Lee",
"get this copied and stamped", "can this be scanned and then signed by Grace?". A clause that
opens with a service's past participle and names no object ("and signed by Lee") shares the
object of the participle before it (reading/shared_object.py), done in the order said; a
participle between "this" and "and" is the service asked, not an adjective of a noun
(lexicon.described_by_participles); "this" before a participle is no modifier of a service
the office lacks (screen/service.py). Before: "Which item do you mean to be signed?", or "I
can't this photocopied", and the run failed."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office
from helpers.dataset_offices import default_office, harbour_office

Row = tuple[str, str | None, str | None, str | None]


def _parse(office: Office, text: str, who: str) -> list[Row]:
    frame = InstructionParser(office).parse(text, who)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "I need this photocopied and signed by Lee",
            [("copy", "document", "mao", None), ("sign", "document", "mao", "lee")],
        ),
        (
            "I need this copied and then signed by Zhang",
            [("copy", "document", "mao", None), ("sign", "document", "mao", "zhang")],
        ),
        (
            "get this copied and stamped",
            [("copy", "document", "mao", None), ("seal", "document", "mao", None)],
        ),
        (
            "get my contract copied and stamped",
            [("copy", "document", "mao", None), ("seal", "document", "mao", None)],
        ),
        ("I need this photocopied", [("copy", "document", "mao", None)]),
        ("I want this copied", [("copy", "document", "mao", None)]),
    ],
)
def test_default_office(text: str, tasks: list[Row]) -> None:
    assert _parse(default_office(), text, "mao") == tasks


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "can my document be scanned and then signed by Grace?",
            [("copy", "document", "may", None), ("sign", "document", "may", "grace")],
        ),
        (
            "can this be scanned and then signed by Grace?",
            [("copy", "document", "may", None), ("sign", "document", "may", "grace")],
        ),
        (
            "I need this scanned and signed by Mark",
            [("copy", "document", "may", None), ("sign", "document", "may", "mark")],
        ),
        ("I need this scanned", [("copy", "document", "may", None)]),
    ],
)
def test_harbour(text: str, tasks: list[Row]) -> None:
    assert _parse(harbour_office(), text, "may") == tasks


def test_a_second_verb_with_its_own_object_is_not_given_the_first_ones() -> None:
    # "sign for the parcel" is no signature on the memo: not read as the memo's
    frame = InstructionParser(default_office()).parse("copy my memo and sign for the parcel", "mao")
    assert ("sign", "document", "mao", None) not in [
        (t.kind, t.item, t.owner, t.actor) for t in frame.tasks
    ]


def test_a_participle_before_its_noun_is_still_an_adjective() -> None:
    # "courier my signed letter": the letter is already signed, no signature asked
    frame = InstructionParser(default_office()).parse("bring me my signed letter", "mao")
    assert all(t.kind != "sign" for t in frame.tasks), frame


async def test_copied_then_signed_runs_to_done_in_the_order_said() -> None:
    run = await run_instruction(
        default_office(), "mao", "I need this photocopied and signed by Lee"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "signed by Lee Ming" in run.stm.trace.summary, run.stm.trace.summary
