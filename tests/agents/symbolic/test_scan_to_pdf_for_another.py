"""A scan to PDF for someone else reaches them (issue 23): "scan my document to PDF and send
it to Wang" read as a copy for Wang. Before, the planner dropped the recipient for a file sent
by message, the operator was told to send the PDF "to its owner", the simulated operator did,
and the final words still said it was sent to Wang (a false claim, a lost delivery). Now the
operator's question and code name whom to send it to (``SendQR.send_to``, by name), the
simulated operator sends it to the person its message names (``sim.file_recipient``), the
oracle plans and the dataset's goal require the same, the consent guard lets it go only to a
person the requester named, and the phrasings judge credits the PDF to whom it was sent.
Default office with a scan at its printer, harbour with its scanner made to scan to PDF."""

from __future__ import annotations

import asyncio
import json
import sys
from pathlib import Path
from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.agents.oracle.plan import build_plan
from assistantx.agents.registry import reasoner_factory
from assistantx.core.actions import SendQR
from assistantx.core.office import Office, parse_office
from assistantx.core.settings import Settings
from assistantx.core.task_spec import BaseInstruction, Part
from assistantx.core.wording import purpose_text
from assistantx.runtime import consent
from assistantx.sim.file_recipient import file_recipient
from assistantx.sim.run import run_in_sim
from helpers.consent_memory import answered, memory
from helpers.dataset_offices import HARBOUR_FILE, default_office_that_scans, harbour_office
from helpers.dataset_tasks import verify_every_variant

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "bench"))
from _phrasing_judge import Case, judge  # bench/ is no package: on the path above

from helpers.yaml_files import raw_yaml


def _default() -> Office:
    return default_office_that_scans("scan", "file")


def _harbour_pdf() -> Office:
    """Harbour with its scanner scanning to PDF (its own electronic file type), not to paper."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    op = next(o for o in raw["operations"] if o["id"] == "scan")
    op["product"], op["name"] = "file", "scan to PDF"
    next(f for f in raw["facilities"] if f["id"] == "scanner")["products"] = ["file"]
    return parse_office(raw)


OFFICES = {"default": _default, "harbour": _harbour_pdf}

# (office, requester, words, recipient): the class's analogues and variants with other words
FOR_ANOTHER = [
    ("default", "lee", "could my document be scanned to pdf and sent to Wang?", "wang"),
    ("default", "lee", "scan my document to PDF and send it to Wang", "wang"),
    ("default", "zhang", "please scan my document into a PDF for Chen", "chen"),
    ("harbour", "may", "could my document be scanned to pdf and sent to Rose?", "rose"),
    ("harbour", "may", "scan my document to PDF and email it to Rose Adeyemi please", "rose"),
    ("harbour", "will", "please scan my document to pdf for Grace", "grace"),
]


@pytest.mark.parametrize(("office_id", "requester", "text", "to"), FOR_ANOTHER)
async def test_the_pdf_reaches_the_person_it_is_for(
    office_id: str, requester: str, text: str, to: str
) -> None:
    office = OFFICES[office_id]()
    run = await run_instruction(office, requester, text)
    summary = run.stm.trace.summary
    assert run.stm.trace.outcome == "done", summary
    made = f"file:{requester}"
    assert run.sim.world.check({"received": [to, made]})
    assert not run.sim.world.check({"received": [requester, made]})  # not to the owner
    assert run.sim.world.check({"holds": [requester, f"document:{requester}"]})  # paper back
    name = office.person(to).name
    codes = [r.action for r in run.stm.trace.actions() if isinstance(r.action, SendQR)]
    work = [c for c in codes if c.purpose == "copy"]
    assert [c.send_to for c in work] == [to]
    told = " ".join(m.text for m in run.sim.messenger.sent if m.chat.id == work[0].contact)
    assert f"send the electronic file to {name}" in told
    assert f"sent to {name} by message" in summary
    assert to not in {c.contact for c in codes}  # nobody carries anything to them


@pytest.mark.parametrize(
    ("office_id", "requester", "text"),
    [
        ("default", "lee", "scan my document to PDF please"),
        ("default", "wang", "could my document be scanned to pdf?"),
        ("harbour", "may", "scan my document to pdf for me"),
    ],
)
async def test_must_not_change_a_pdf_for_its_owner_goes_to_its_owner(
    office_id: str, requester: str, text: str
) -> None:
    office = OFFICES[office_id]()
    run = await run_instruction(office, requester, text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"received": [requester, f"file:{requester}"]})
    codes = [r.action for r in run.stm.trace.actions() if isinstance(r.action, SendQR)]
    assert all(c.send_to is None for c in codes)
    told = " ".join(m.text for m in run.sim.messenger.sent if m.chat.id != requester)
    assert "send the electronic file to its owner" in told
    assert "sent to you by message" in run.stm.trace.summary


async def test_must_not_change_a_paper_scan_for_another_is_carried_to_them() -> None:
    """Harbour as it is: its scanner makes a paper scan, which the robot brings to Rose."""
    run = await run_instruction(harbour_office(), "may", "scan my document and send it to Rose")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["rose", "scan:may"]})
    codes = [r.action for r in run.stm.trace.actions() if isinstance(r.action, SendQR)]
    assert all(c.send_to is None for c in codes)


def test_the_code_names_whom_to_send_it_to_never_an_id() -> None:
    office = _default()
    said = purpose_text(office, "copy", "document:lee", you="mao", operation="scan", send_to="wang")
    assert "send the electronic file to Wang Fang and put it back" in said
    assert "wang" not in said.replace("Wang", "")
    own = purpose_text(office, "copy", "document:lee", you="mao", operation="scan", send_to="lee")
    assert "send the electronic file to its owner" in own
    mine = purpose_text(office, "copy", "document:lee", you="mao", operation="scan", send_to="mao")
    assert "send the electronic file to yourself" in mine


@pytest.mark.parametrize(
    ("told", "expected"),
    [
        (
            "... take Lee Ming's document out, scan it, send the PDF to Wang Fang and put it back.",
            "wang",
        ),
        ("... scan it, send the electronic file to its owner and put it back.", "lee"),
        ("... scan it, send the electronic file to yourself and put it back.", "mao"),
        ("... scan it and put the original and the scan back.", "lee"),
        ("... scan it, send the PDF to the moon and put it back.", "lee"),  # nobody known
    ],
)
def test_the_operator_sends_it_to_whom_the_message_names(told: str, expected: str) -> None:
    assert file_recipient(_default(), told, "lee", "mao") == expected


def _work_code(to: str) -> SendQR:
    return SendQR(contact="mao", item="document:lee", purpose="copy", operation="scan", send_to=to)


def test_the_guard_sends_the_pdf_only_to_a_person_the_requester_named() -> None:
    office = _default()
    stm = memory("lee", "scan my document to PDF and send it to Wang")
    answered(stm, "mao")
    assert consent.check(office, stm, _work_code("wang")) is None
    assert consent.check(office, stm, _work_code("lee")) is None  # the owner and requester
    refused = consent.check(office, stm, _work_code("chen"))  # Chen was never named
    assert refused is not None and refused.rule == "not_a_party"
    unnamed = memory("lee", "scan my document to PDF please")
    answered(unnamed, "mao")
    refused = consent.check(office, unnamed, _work_code("wang"))
    assert refused is not None and refused.rule == "not_a_party"


def test_the_oracle_tells_the_operator_and_requires_the_recipient_to_receive_it() -> None:
    base = BaseInstruction(
        id="s1",
        requester="lee",
        text="scan my document to PDF and send it to Wang",
        parts=(Part(kind="copy", operation="scan", to="wang"),),
    )
    plan = build_plan(base, _default())
    assert {"received": ["wang", "file:lee"]} in plan.goal
    assert {"received": ["lee", "file:lee"]} not in plan.goal
    [code] = [c for v in plan.visits for c in v.codes if c.purpose == "copy"]
    assert code.send_to == "wang"


@pytest.mark.parametrize(
    ("office_id", "requester", "to", "text"),
    [
        ("default", "lee", "wang", "scan my document to PDF and send it to Wang"),
        ("harbour", "may", "rose", "scan my document to PDF and send it to Rose"),
    ],
)
def test_a_generated_scan_for_another_is_solved_by_the_oracle(
    office_id: str, requester: str, to: str, text: str
) -> None:
    base = BaseInstruction(
        id="scan2",
        requester=requester,
        text=text,
        parts=(Part(kind="copy", operation="scan", to=to),),
    )
    tasks = asyncio.run(verify_every_variant(OFFICES[office_id](), base))
    achievable = [t for t in tasks if t.achievable]
    assert achievable
    assert all({"received": [to, f"file:{requester}"]} in t.goal for t in achievable)


def test_the_judge_credits_the_pdf_to_whom_it_was_sent() -> None:
    office = _default()
    text = "scan my document to PDF and send it to Wang"
    factory = reasoner_factory("symbolic", office, Settings())
    run = asyncio.run(run_in_sim(office, "lee", text, factory, reasoner_name="symbolic"))
    trace = json.loads(run.trace.model_dump_json())
    assert trace["outcome"] == "done", trace["summary"]

    def case(recipient: str) -> Case:
        fields = {"recipient": recipient, "item": "file"}
        return Case.model_validate(
            {"id": "c", "as": "lee", "text": text, "expect": "deliver", **fields}
        )

    theirs = judge(case("wang"), trace, office)
    assert (theirs.right, theirs.wrong_physical) == (True, None), theirs.why
    assert not judge(case("lee"), trace, office).right
