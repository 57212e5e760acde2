"""Services that do not hand the item back (issue 23, item 5): a fax that sends a document
outside the office (nothing comes back, nobody collects) and a scan to PDF whose product is an
electronic file sent by message, not put into the locker; outcomes told with the operation's
own words. Embedded planner, oracle and the dataset's check alike."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.agents.oracle.plan import build_plan
from assistantx.core.office import DEFAULT_OFFICE, Office, parse_office
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from assistantx.evaluation.dataset.generate import _task, classify, verify_tasks
from helpers.yaml_files import raw_yaml


def _office(**op: Any) -> Office:
    raw: dict[str, Any] = raw_yaml(DEFAULT_OFFICE)
    raw["item_types"].append({"id": "pdf", "name": "PDF", "kind": "electronic"})
    raw["operations"] = [o for o in raw["operations"] if o["id"] != "copy"]
    raw["operations"].append({"verbs": [op["name"]], "input": "document", **op})
    for f in raw["facilities"]:
        if f["id"] == "printer":
            f["operations"], f["products"] = ["print", op["id"]], ["printout"]
    return parse_office(raw)


@pytest.fixture(scope="module")
def fax() -> Office:
    return _office(id="fax", name="fax", sends_out=True, destination_asked="the fax number")


@pytest.fixture(scope="module")
def scan() -> Office:
    return _office(id="scan", name="scan", product="pdf", done="scanned to PDF")


async def test_a_fax_sent_outside_is_not_handed_back(fax: Office) -> None:
    run = await run_instruction(fax, "lee", "Please fax my document to the county tax office")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "your document was faxed" in run.stm.trace.summary
    assert run.sim.world.check({"heated": "document:lee"})
    assert run.sim.world.holder["document:lee"] == "print_room"  # it stays at the fax
    codes = [r.action for r in run.stm.trace.actions() if r.action.type == "send_qr"]
    assert [c.purpose for c in codes] == ["deposit", "heat"]  # nobody collects it
    told = [m.text for m in run.sim.messenger.sent if m.chat.id == "mao"]
    assert not any("put it back" in t for t in told)


async def test_who_faxes_it_is_told_where_to_in_the_question_and_the_code(fax: Office) -> None:
    run = await run_instruction(fax, "lee", "Please fax my document to the county tax office")
    question, code = [m.text for m in run.sim.messenger.sent if m.chat.id == "mao"]
    assert "could you fax Lee Ming's document to the county tax office?" in question
    assert question.endswith("The robot will bring it to you at the printer.")
    assert "take Lee Ming's document out and fax it to the county tax office." in code
    [sent] = run.sim.world.sent_out()
    assert sent.detail["item"] == "document:lee" and sent.detail["by"] == "mao"


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("Please fax my document to the county tax office", "the county tax office"),
        ("could you fax my contract to +44 20 7946 0000 please", "+44 20 7946 0000"),
        # a capitalized name after the fax's "to" is a place outside, not a colleague to find
        ("fax my document to Harlow & Sons Ltd, thanks!", "Harlow & Sons Ltd"),
        ("pls fax my contract to Dr Okafor at St Mary's clinic", "Dr Okafor at St Mary's clinic"),
    ],
)
async def test_the_outcome_names_where_the_fax_went_in_the_requesters_words(
    fax: Office, text: str, where: str
) -> None:
    run = await run_instruction(fax, "lee", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert f"your document was faxed to {where}" in run.stm.trace.summary


async def test_a_fax_with_no_destination_asks_where_before_anything_moves(fax: Office) -> None:
    run = await run_instruction(fax, "lee", "please fax my document")
    told = [m.text for m in run.sim.messenger.sent if m.chat.id == "lee"]
    assert told and "Where should I fax it to? Please give me the fax number." in told[0]
    assert not [r for r in run.stm.trace.actions() if r.action.type in ("send_qr", "move")]


async def test_the_oracle_faxes_out_to_the_named_destination(fax: Office) -> None:
    part = Part(kind="heat", operation="fax", destination="the county tax office")
    base = BaseInstruction(
        id="f1", requester="lee", text="fax my form to the tax office", parts=(part,)
    )
    check_base(base, fax)
    assert part.task("lee", fax).destination == "the county tax office"
    plan = build_plan(base, fax)
    assert plan.deliveries == [] and {"heated": "document:lee"} in plan.goal
    pools = classify(base, fax)
    await verify_tasks(fax, [_task(pools["L1"][0], fax, 1)])


async def test_a_scan_to_pdf_is_sent_by_message_and_the_paper_comes_back(scan: Office) -> None:
    run = await run_instruction(scan, "lee", "Please scan my document")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "scanned to PDF" in run.stm.trace.summary and "by message" in run.stm.trace.summary
    assert run.sim.world.check({"received": ["lee", "pdf:lee"]})
    assert run.sim.world.check({"holds": ["lee", "document:lee"]})
    assert "pdf:lee" not in run.sim.world.holder  # never in the locker: it is a file


async def test_the_oracle_scans_to_pdf_alike(scan: Office) -> None:
    base = BaseInstruction(
        id="s1", requester="lee", text="scan my form to PDF", parts=(Part(kind="copy"),)
    )
    plan = build_plan(base, scan)
    assert {"received": ["lee", "pdf:lee"]} in plan.goal
    pools = classify(base, scan)
    await verify_tasks(scan, [_task(pools["L1"][0], scan, 1)])


def test_only_the_send_out_service_verb_makes_a_destination_outside() -> None:
    """A courier whose verbs include "send out": "courier it to <a firm>" is a place outside,
    but a plain "send ... to Yang" is still about colleagues (two of them share "Yang")."""
    from assistantx.agents.symbolic import InstructionParser

    office = _office(id="courier", name="courier", verbs=["send out", "courier"], sends_out=True)
    parser = InstructionParser(office)
    sent = parser.parse("courier my document to Harlow & Sons Ltd", "lee")
    assert [(t.operation, t.destination) for t in sent.tasks] == [("courier", "Harlow & Sons Ltd")]
    asked = parser.parse("send my slides to Yang", "lee")
    assert asked.tasks == [] and asked.question and "Yang" in asked.question


@pytest.mark.parametrize(
    ("text", "where"),
    [
        (
            "fax my document to Mrs Abernethy at 14 Rosebery Crescent, Edinburgh please",
            "Mrs Abernethy at 14 Rosebery Crescent, Edinburgh",
        ),
        ("please fax my document to 3 Quay Street, Leeds LS1 4DY", "3 Quay Street, Leeds LS1 4DY"),
    ],
)
async def test_who_sends_it_is_told_the_whole_address_past_its_comma(
    fax: Office, text: str, where: str
) -> None:
    """A person at an address with the town after a comma (C1 of round 12): the sender's
    question and code name all of it, and the outcome says it back."""
    run = await run_instruction(fax, "lee", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    question, code = [m.text for m in run.sim.messenger.sent if m.chat.id == "mao"]
    assert f"to {where}?" in question and f"fax it to {where}." in code
    assert f"your document was faxed to {where}" in run.stm.trace.summary


async def test_a_clause_after_the_address_comma_is_not_sent_to(fax: Office) -> None:
    run = await run_instruction(fax, "lee", "fax my document to 9 Mill Lane, it has to go today")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "your document was faxed to 9 Mill Lane" in run.stm.trace.summary
    assert "it has to go" not in " ".join(m.text for m in run.sim.messenger.sent)
