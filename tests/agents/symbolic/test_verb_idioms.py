"""A task verb inside a fixed phrase ("take care of that", "take a look at it") asks for no
hand-over: "Kai has to sign my form, could you take care of that?" is the signature it points
at, as "could you see to that?" is, never a question of whom to take the form to. A request
with the verb itself ("take my stapler to Zhang") is read as before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import build_factory
from assistantx.core.office import Office, load_office
from assistantx.core.settings import Settings
from assistantx.sim.office import SimOffice
from helpers.office import run_one, sim_assistant
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "Zhang has to sign my contract, could you take care of that?",
        "Zhang has to sign my contract. Can you take care of it?",
        "Zhang needs to sign my form, pls take care of that",
        "could you take charge of getting Zhang to sign my contract?",
    ],
)
def test_take_care_of_points_at_the_work_said(text: str) -> None:
    frame = _lee(text)
    assert [(t.kind, t.actor, t.recipient) for t in frame.tasks] == [("sign", "zhang", "lee")], (
        frame
    )


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("take my stapler to Zhang", "zhang"),
        ("can you take Zhang my stapler", "zhang"),
        ("take care to bring my stapler to Zhang", "zhang"),
    ],
)
def test_the_verb_itself_still_takes(text: str, recipient: str) -> None:
    frame = _lee(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [("stapler", recipient)], frame


async def test_a_signature_asked_with_take_care_of_is_done_end_to_end() -> None:
    office: Office = load_office()
    sim = SimOffice(office)
    assistant = sim_assistant(sim, build_factory(office, Settings()))
    text = "Zhang has to sign my contract, could you take care of that?"
    stm = await run_one(sim, assistant, "lee", text)
    assert stm.trace.outcome == "done"
    assert not [r for r in stm.trace.actions() if r.refused]
    assert sim.world.check({"signed": ["document:lee", "zhang"]})
    assert sim.world.check({"holds": ["lee", "document:lee"]})
