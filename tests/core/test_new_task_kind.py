"""A new task kind is one entry of the table (issue 23, item 4).

An "approve" kind (a person approves the requester's paper, as a signer signs it) is added
to the table at run time, one :class:`KindSpec` with its shape, steps, milestone and words,
and no other code: the schema, the dataset's parts and the lock take it, and the optimal
policy runs it to done in the simulated office, where the approver is asked with its words,
gets a code for its own work step and leaves its milestone true.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from pydantic import ValidationError

from assistantx.agents.hybrid import build_factory
from assistantx.agents.llm.grounding import RequestWords, ungrounded_action
from assistantx.agents.oracle.optimal import OptimalReasoner
from assistantx.agents.oracle.plan import build_plan
from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic import build_factory as symbolic_factory
from assistantx.core import task_kinds
from assistantx.core.actions import SendQR
from assistantx.core.goals import parse_milestone
from assistantx.core.office import load_office
from assistantx.core.ports.lock import QRCode
from assistantx.core.settings import Settings
from assistantx.core.task_kinds import KindSpec
from assistantx.core.task_schema import Part, Task
from assistantx.core.task_spec import BaseInstruction, check_base
from assistantx.sim.office import SimOffice
from assistantx.sim.run import run_in_sim
from fakes.fixtures import scripted_llm  # noqa: F401
from fakes.scripted_llm import ScriptedLLM, json_reply
from helpers.added_kinds import kind_added, signing_kind
from helpers.llm_office import llm_model, llm_settings
from helpers.office import run_one, sim_assistant

APPROVE = signing_kind("approve", "approve", "approved", "approver", words=("approve", "approval"))


@pytest.fixture
def approve() -> Iterator[KindSpec]:
    with kind_added(APPROVE):
        yield APPROVE


def _code(purpose: str) -> QRCode:
    return QRCode.model_validate(
        {
            "code_id": "c1",
            "payload": "p",
            "lock_id": "locker",
            "instruction_id": "ins-1",
            "person": "wang",
            "purpose": purpose,
            "item": "document:lee",
            "issued_at": 0.0,
            "expires_at": 1.0,
        }
    )


def test_a_kind_outside_the_table_is_refused_with_the_known_ones() -> None:
    with pytest.raises(ValidationError, match="unknown task kind 'approve'; known: transfer"):
        Task(kind="approve", recipient="lee")
    with pytest.raises(ValidationError, match="unknown code purpose 'approve'"):
        _code("approve")
    assert Part(kind="approve").task_kind() == "produce"  # not a part kind: a product's name


def test_the_added_kind_is_a_kind_a_part_and_a_purpose(approve: KindSpec) -> None:
    assert Task(kind="approve", recipient="lee").kind == "approve"
    assert _code("approve").purpose == "approve"
    assert Part(kind="approve", signer="wang").task_kind() == "approve"
    assert "approve" in task_kinds.work_purposes()
    assert parse_milestone({"approved": ["document:lee", "wang"]}) == (
        "approved",
        ("document:lee", "wang"),
    )


def test_an_entry_that_clashes_with_the_table_is_refused(approve: KindSpec) -> None:
    with pytest.raises(ValueError, match="the id 'approve' is taken"):
        task_kinds.add(APPROVE)
    with pytest.raises(ValueError, match="the shape 'treat' is the office's"):
        task_kinds.add(
            KindSpec(
                id="laminate", parts=(), milestone="laminated", todo="", done="", shape="treat"
            )
        )
    with pytest.raises(ValueError, match="'sign' is a built-in task kind"):
        task_kinds.remove("sign")


async def test_the_added_kind_runs_to_done_in_the_simulated_office(approve: KindSpec) -> None:
    office = load_office()
    text = "Please get my document approved by Wang."
    base = BaseInstruction(
        id="approve-1", requester="lee", text=text, parts=(Part(kind="approve", signer="wang"),)
    )
    check_base(base, office)
    plan = build_plan(base, office)
    assert {"approved": ["document:lee", "wang"]} in plan.goal

    run = await run_in_sim(office, "lee", text, lambda: OptimalReasoner(office, base))

    assert run.trace.outcome == "done", run.trace.summary
    assert run.sim.check(plan.goal) == [True] * len(plan.goal)
    to_wang = [m.text for m in run.sim.messenger.sent if m.chat.id == "wang"]
    assert any("approve" in t for t in to_wang), to_wang  # asked with the kind's words
    assert any("approve it and put it back" in t for t in to_wang), to_wang  # its locker step
    # the document went back to nobody but its owner
    moved_to = {e.detail["to"] for e in run.sim.world.handovers()}
    assert moved_to <= {"lee", "wang", "locker"}, moved_to


def test_the_model_path_grounds_the_added_kind_by_its_words(approve: KindSpec) -> None:
    """A code for the added kind's work is grounded when the request says one of its words,
    and refused when it does not (the model's reading never adds work nobody asked for)."""
    office = load_office()
    code = SendQR(contact="wang", item="document:lee", purpose="approve")
    asked = RequestWords(office, ["Please get my document approved by Wang."])
    assert ungrounded_action(asked, "lee", code) is None
    not_asked = RequestWords(office, ["Please bring my document to Wang."])
    assert ungrounded_action(not_asked, "lee", code) == "the request never asks to approve anything"


async def test_the_embedded_planner_runs_the_added_kind_from_the_models_reading(
    approve: KindSpec,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    """The hybrid reasoner: the model (scripted) reads the request as the added kind, told of
    it in its prompt; the symbolic planner, with no code of the kind, runs it to done."""
    office = load_office()
    scripted_llm.script(
        "understanding",
        json_reply(
            {"sure": True, "tasks": [{"kind": "approve", "item": "document", "actor": "Wang Fang"}]}
        ),
    )
    sim = SimOffice(office)
    factory = build_factory(office, llm_settings(scripted_llm), model=llm_model(scripted_llm))
    try:
        stm = await run_one(
            sim, sim_assistant(sim, factory), "lee", "Please get my document approved by Wang."
        )
    finally:
        await factory.model.stop()

    assert stm.trace.outcome == "done", stm.trace.summary
    assert sim.world.check({"approved": ["document:lee", "wang"]})
    assert sim.world.check({"holds": ["lee", "document:lee"]})
    prompt = scripted_llm.requests_for("understanding")[0]
    assert "sign, seal, approve" in prompt.messages[0]["content"]


async def test_the_embedded_reader_reads_and_runs_the_added_kind(approve: KindSpec) -> None:
    """The symbolic reasoner, built after the kind was added and with no code of it, reads
    the kind from its words ("approved", "approval") and runs it to done: the approver is
    asked with the kind's words and the requester's document comes back approved."""
    office = load_office()
    sim = SimOffice(office)
    factory = symbolic_factory(office, Settings())
    stm = await run_one(
        sim, sim_assistant(sim, factory), "lee", "Please get my document approved by Wang."
    )

    assert stm.trace.outcome == "done", stm.trace.summary
    assert sim.world.check({"approved": ["document:lee", "wang"]})
    assert sim.world.check({"holds": ["lee", "document:lee"]})
    to_wang = [m.text for m in sim.messenger.sent if m.chat.id == "wang"]
    assert any("approve" in t for t in to_wang), to_wang


def test_the_embedded_reader_asks_who_approves_when_nobody_is_named(approve: KindSpec) -> None:
    frame = InstructionParser(load_office()).parse("Please get my document approved.", "lee")
    assert frame.tasks == [] and frame.question and "Who" in frame.question
