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
import yaml
from symbolic_run import run_instruction

from assistantx.core.office import DEFAULT_OFFICE, Office, parse_office


@pytest.fixture(scope="module")
def office() -> Office:
    raw: dict[str, Any] = yaml.safe_load(DEFAULT_OFFICE.read_text(encoding="utf-8"))
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
