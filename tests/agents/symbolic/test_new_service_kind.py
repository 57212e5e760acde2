"""A new service is an office-file entry and nothing else (issue 23, item 4).

A fax and a binding machine are added to a copy of the default office: one ``operations:``
entry each and the facility that offers it. The embedded reasoner runs each request to done
in the simulated office, the locker code names the office's own verb, and the requester is
told the outcome with that verb ("faxed", the irregular "bound"), never with another
service's ("heated").
"""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import DEFAULT_OFFICE, Office, parse_office
from assistantx.core.task_spec import BaseInstruction, Part
from assistantx.evaluation.dataset.generate import verify_tasks
from helpers.dataset_tasks import every_task
from helpers.yaml_files import raw_yaml


@pytest.fixture(scope="module")
def office() -> Office:
    raw: dict[str, Any] = raw_yaml(DEFAULT_OFFICE)
    raw["operations"] += [
        {"id": "fax", "name": "fax", "verbs": ["fax"], "input": "document"},
        {"id": "bind", "name": "bind", "verbs": ["bind"], "input": "document"},
    ]
    raw["facilities"] += [
        {
            "id": "fax_machine",
            "name": "telefax",
            "location": "print_room",
            "operations": ["fax"],
            "guards": ["xu"],
        },
        {
            "id": "binder",
            "name": "binding machine",
            "location": "print_room",
            "operations": ["bind"],
            "guards": ["mao"],
        },
    ]
    return parse_office(raw, "office-with-new-services")


@pytest.mark.parametrize(
    ("text", "verb", "done"),
    [
        ("Please fax my contract.", "fax", "faxed"),
        ("Could you bind my report?", "bind", "bound"),
    ],
)
async def test_a_new_service_runs_to_done_and_is_told_with_its_own_verb(
    office: Office, text: str, verb: str, done: str
) -> None:
    run = await run_instruction(office, "lee", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    codes = [m.text for m in run.sim.messenger.sent if "locker" in m.text.lower()]
    assert any(f"{verb} it and put it back" in c for c in codes), codes
    told = run.sim.messenger.sent[-1]
    assert told.chat.id == "lee"
    assert f"your document was {done} and handed to you" in told.text, told.text
    assert "heated" not in told.text
    # the document went back to nobody but its owner
    assert {
        e.detail["to"] for e in run.sim.world.handovers() if e.detail.get("to") != "locker"
    } <= {"lee"}


async def test_a_service_that_consumes_the_item_hands_nothing_back() -> None:
    """A shredder (``consumes: true``): the document goes in and stays shredded; the requester
    is told "shredded", and no code asks anyone to take it out again."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_OFFICE)
    raw["operations"].append(
        {"id": "shred", "name": "shred", "verbs": ["shred"], "input": "document", "consumes": True}
    )
    raw["facilities"].append(
        {
            "id": "shredder",
            "name": "paper shredder",
            "location": "print_room",
            "operations": ["shred"],
            "guards": ["xu"],
        }
    )
    office = parse_office(raw, "office-with-a-shredder")
    # the oracle plans it the same way, and achieves every variant the generator makes of it
    base = BaseInstruction(
        id="s1",
        requester="lee",
        text="shred my contract",
        parts=(Part(kind="heat", operation="shred"),),
    )
    await verify_tasks(office, every_task(office, base))
    run = await run_instruction(office, "lee", "Please shred my old contract.")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"heated": "document:lee"})
    assert run.sim.world.holder["document:lee"] == "print_room"
    told = run.sim.messenger.sent[-1].text
    assert "your document was shredded" in told and "handed" not in told, told
    codes = [m.text for m in run.sim.messenger.sent if "locker" in m.text.lower()]
    assert not any("take your document out of the locker" in c for c in codes), codes


async def test_the_outcome_agrees_with_a_plural_item() -> None:
    """ "your scissors were sharpened": a plural item takes "were" (it read "your clippers
    was sharpened" in a blind round's office); a singular one keeps "was" (above)."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_OFFICE)
    raw["operations"].append(
        {"id": "sharpen", "name": "sharpen", "verbs": ["sharpen", "hone"], "input": "scissors"}
    )
    raw["facilities"].append(
        {
            "id": "whetstone",
            "name": "sharpening bench",
            "location": "print_room",
            "operations": ["sharpen"],
            "guards": ["mao"],
        }
    )
    office = parse_office(raw, "office-with-a-sharpener")
    owner = next(p.id for p in office.people if any(o.type == "scissors" for o in p.owns))
    run = await run_instruction(office, owner, "could you get my scissors sharpened")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    told = run.sim.messenger.sent[-1]
    assert "your scissors were sharpened and handed to you" in told.text, told.text
