"""Blind round 12's reader classes, by mechanism, on sentences of our own against the default
office with a courier service that sends a document outside (the round's own office and
sentences were never read)."""

from __future__ import annotations

import functools
from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import DEFAULT_OFFICE, Office, parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.yaml_files import raw_yaml


@functools.cache
def _courier_office() -> Office:
    raw: dict[str, Any] = raw_yaml(DEFAULT_OFFICE)
    raw["operations"].append(
        {
            "id": "courier",
            "name": "courier",
            "verbs": ["courier", "post"],
            "input": "document",
            "sends_out": True,
            "destination_asked": "the postal address",
        }
    )
    for f in raw["facilities"]:
        if f["id"] == "printer":
            f["operations"] = [*f["operations"], "courier"]
    return parse_office(raw)


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(_courier_office())


def _frame(text: str, who: str = "lee") -> TaskFrame:
    return _parser().parse(text, who)


def _sent(frame: TaskFrame) -> list[tuple[str | None, str | None, str | None]]:
    return [(t.item, t.operation, t.destination) for t in frame.tasks]


# -- 2. a statement says where the item goes, then "can you <send-out verb> it" -------------


@pytest.mark.parametrize(
    ("text", "where"),
    [
        (
            "the document in the printer needs to go out to the county tax office, can you"
            " courier it",
            "the county tax office",
        ),
        (
            "my document needs to go off to 9 Mill Lane, Bath, could you post it?",
            "9 Mill Lane, Bath",
        ),
        ("the document needs to go over to Harlow & Sons, can you courier it", "Harlow & Sons"),
    ],
)
def test_the_statement_before_the_request_says_where_it_goes(text: str, where: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert _sent(frame) == [("document", "courier", where)]  # once, not once per mention


@pytest.mark.parametrize(
    "text",
    [
        "I'm going to the bank, can you courier it",  # the person goes there, not the item
        "she needs to go to the bank, can you courier my document",  # no "it" to refer back
    ],
)
def test_a_place_someone_goes_or_a_far_statement_is_no_destination(text: str) -> None:
    frame = _frame(text)
    assert not [t for t in frame.tasks if t.destination is not None]


async def test_the_courier_is_told_the_statements_destination() -> None:
    text = (
        "the document in the printer needs to go out to the county tax office, can you courier it"
    )
    run = await run_instruction(_courier_office(), "lee", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    [sent] = run.sim.world.sent_out()
    assert sent.detail["item"] == "document:lee"
    assert "courier it to the county tax office." in sent.detail["told"]
    assert run.stm.trace.summary.count("the county tax office") == 1


# -- 3. "my <word the office does not know>" for the requester's one item of the kind --------


@functools.cache
def _permit_office() -> Office:
    """The default office where Lee also owns a signable permit (two signable papers) and
    Mao owns nothing signable."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_OFFICE)
    raw["item_types"].append(
        {"id": "permit", "name": "permit", "kind": "personal", "signable": True}
    )
    for p in raw["people"]:
        if p["id"] == "lee":
            p["owns"] = [*p["owns"], {"type": "permit"}]
        if p["id"] == "mao":
            p["owns"] = [o for o in p["owns"] if o["type"] != "document"]
    return parse_office(raw)


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("Please ask Mao to sign my letter to the owners.", "sign"),
        ("please get my letter signed by Mao", "sign"),
        ("could Mao stamp my memo", "seal"),
    ],
)
def test_my_unknown_paper_is_my_one_signable_item(text: str, kind: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [(kind, "document", "lee")]


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("Please ask Mao to sign my letter to the owners.", "lee"),  # a document and a permit
        ("Please ask Lee to sign my letter.", "mao"),  # nothing of Mao's is signable
        ("please ask Mao to sign the letter", "lee"),  # not said to be the requester's
        ("ask Mao to sign my letter and my memo", "lee"),  # two unknown things
    ],
)
def test_several_or_no_fitting_items_still_ask_which(text: str, who: str) -> None:
    frame = InstructionParser(_permit_office()).parse(text, who)
    assert not frame.tasks and frame.question is not None
    assert frame.question.startswith("Which item do you mean")


async def test_the_one_signable_item_is_named_to_the_signer_and_in_the_outcome() -> None:
    run = await run_instruction(_courier_office(), "lee", "Please ask Mao to sign my letter")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "your document was signed by Mao Jun" in run.stm.trace.summary
    assert run.sim.world.holder["document:lee"] == "lee" or run.sim.world.check(
        {"signed": "document:lee"}
    )


# -- 4. a question about a facility's state, then the problem behind it -------------------


@pytest.mark.parametrize(
    "text",
    [
        "is the printer working? guest says his printout won't come out",
        "is the printer working? Kim says her printout won't come out",
        "is the microwave free? a guest's lunch is still cold",
        "is the coffee machine broken? it keeps leaking",
    ],
)
async def test_a_facility_question_with_a_problem_is_answered_in_words(text: str) -> None:
    run = await run_instruction(_courier_office(), "lee", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert (
        "As far as I know the" in run.stm.trace.summary and "I did nothing" in run.stm.trace.summary
    )
    assert not [r for r in run.stm.trace.actions() if r.action.type in ("send_qr", "move")]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("is the printer working? please print my file", "print"),
        ("is the coffee machine on? I need a coffee", "produce"),
    ],
)
def test_a_request_after_the_question_is_still_a_request(text: str, kind: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [t.kind for t in frame.tasks] == [kind]


def test_a_third_persons_need_after_the_question_is_still_offered() -> None:
    """Near-miss: a need said of a colleague is not a problem report; it is offered as before."""
    frame = _frame("is the printer working? Mao needs his printout")
    assert frame.question is not None and frame.question.startswith("Shall I print")
