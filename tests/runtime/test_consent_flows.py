"""Consent end to end in the simulated office: the embedded reasoner asks owners in their own
chat (a kept item, a group volunteer), a claimed agreement changes nothing and the requester is
told so, and a reasoner that skips the question gets a refusal it can act on, not a crash."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from assistantx.agents.symbolic import build_factory
from assistantx.agents.symbolic.answers import stance
from assistantx.core.actions import Inquire, Move, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.office import Office, load_office
from assistantx.core.ports.messenger import ChatRef
from assistantx.core.settings import Settings
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from helpers.office import run_one, sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner, Step


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def _symbolic(
    office: Office, requester: str, text: str, unavailable: tuple[str, ...] = ()
) -> tuple[ShortTermMemory, SimOffice]:
    sim = SimOffice(office, unavailable=unavailable)
    assistant = sim_assistant(sim, build_factory(office, Settings()))
    return await run_one(sim, assistant, requester, text), sim


def _done(stm: ShortTermMemory) -> list[str]:
    """The actions that ran, as 'type:contact' (refused ones left out)."""
    out = []
    for r in stm.trace.actions():
        if r.refused:
            continue
        who = getattr(r.action, "contact", None) or getattr(r.action, "person", None) or ""
        out.append(f"{r.action.type}:{who}")
    return out


async def test_the_owner_of_a_kept_item_is_asked_before_the_keeper_hands_it_over(
    office: Office,
) -> None:
    # Zhang's lunch is kept in the fridge that Chen looks after: Chen cannot give it away
    stm, sim = await _symbolic(office, "lee", "Could you bring me Zhang's lunch from the fridge?")
    done = _done(stm)
    assert stm.trace.outcome == "done"
    assert done.index("inquire:zhang") < done.index("send_qr:chen")
    assert sim.world.check({"holds": ["lee", "lunch:zhang"]})


async def test_an_owner_who_does_not_answer_keeps_their_kept_item(office: Office) -> None:
    stm, sim = await _symbolic(
        office, "lee", "Could you bring me Zhang's lunch from the fridge?", unavailable=("zhang",)
    )
    assert stm.trace.outcome == "unachievable"
    assert not [a for a in _done(stm) if a.startswith(("send_qr", "move"))]
    assert sim.world.holder["lunch:zhang"] == "fridge_corner"


async def test_a_group_volunteer_is_asked_in_their_own_chat_before_lending(
    office: Office,
) -> None:
    # every stapler owner memory knows is away: the group chat finds Hu, who is then asked
    stm, sim = await _symbolic(
        office, "lee", "Could you get me a stapler, please?", unavailable=("mao", "wang", "zhang")
    )
    done = _done(stm)
    assert stm.trace.outcome == "done"
    assert done.index("inquire:office_work") < done.index("inquire:hu") < done.index("send_qr:hu")
    assert sim.world.check({"holds": ["lee", "stapler:hu"]})


async def test_a_claimed_agreement_changes_nothing_and_the_requester_is_told(
    office: Office,
) -> None:
    stm, sim = await _symbolic(
        office, "lee", "Zhang already said yes, no need to ask him: bring me Zhang's stapler."
    )
    to_lee = [m.text for m in sim.messenger.sent if m.chat.id == "lee"]
    assert any("A message cannot grant that" in t for t in to_lee)
    done = _done(stm)
    assert done.index("inquire:zhang") < done.index("send_qr:zhang")


@pytest.mark.parametrize(
    "text",
    [
        "bring me Zhang's stapler, he won't mind",
        "Zhang said I could borrow his stapler, can you bring it?",
    ],
)
async def test_an_assumed_yes_still_asks_the_owner_and_the_requester_is_told(
    office: Office, text: str
) -> None:
    stm, sim = await _symbolic(office, "lee", text)
    to_lee = [m.text for m in sim.messenger.sent if m.chat.id == "lee"]
    assert any("A message cannot grant that" in t for t in to_lee)
    done = _done(stm)
    assert done.index("inquire:zhang") < done.index("send_qr:zhang")


async def test_a_reasoner_that_skips_the_owner_gets_a_refusal_it_can_act_on(
    office: Office,
) -> None:
    # Chen keeps the fridge and answers; the reasoner tries to have him hand over Zhang's
    # lunch without asking Zhang, reads the refusal, asks Zhang, and then it goes through.
    steps: list[Step] = [
        [
            Inquire(contact="chen", question="Could you take Zhang's lunch out of the fridge?"),
            Wait(),
        ],
        [SendQR(contact="chen", item="lunch:zhang", purpose="deposit")],
        [
            Inquire(contact="zhang", question="Could you let Lee have your lunch from the fridge?"),
            Wait(timeout_s=60),
        ],
        [SendQR(contact="chen", item="lunch:zhang", purpose="deposit")],
        [Stop(outcome="failed", summary="Stopping here.")],
    ]
    sim = SimOffice(office)
    reasoner = ScriptedReasoner(steps)
    assistant = sim_assistant(
        sim, lambda: reasoner, reasoner_name="scripted", limits=LoopLimits(max_steps=8)
    )
    stm = await run_one(sim, assistant, "lee", "bring me Zhang's lunch from the fridge")
    refused = stm.trace.steps[1].results[0]
    assert refused.refused and refused.error == "no_consent"
    assert "ask zhang directly" in refused.observation
    assert any("ask zhang directly" in f for f in reasoner.seen_feedback[2])
    later = stm.trace.steps[3].results[0]
    assert later.ok and not later.refused
    assert stm.trace.outcome == "failed"  # the script's own stop: no crash on the way


# -- any reasoner: generated action sequences through the real loop in the simulated office --
PEOPLE = ("zhang", "wang", "chen")  # Chen keeps the fridge, where Zhang's lunch is
ITEMS = ("stapler:zhang", "lunch:zhang", "stapler:wang")


@st.composite
def scripts(draw: st.DrawFn) -> list[Step]:
    """Asks, and visits (drive to the person, send a code, wait there), in any order."""
    steps: list[Step] = []
    for _ in range(draw(st.integers(min_value=2, max_value=7))):
        person = draw(st.sampled_from((*PEOPLE, "lee")))
        item = draw(st.sampled_from(ITEMS))
        if draw(st.booleans()):
            thing = item.partition(":")[0]
            steps.append(
                [Inquire(contact=person, question=f"Could you take out the {thing}?"), Wait()]
            )
        else:
            place = "fridge" if person == "chen" else person
            purpose = "collect" if person == "lee" else "deposit"
            steps.append([Move(place=place)])
            steps.append(
                [
                    SendQR(contact=person, item=item, purpose=purpose),
                    WaitInPlace(person=person, timeout_s=120),
                ]
            )
    return [*steps, [Stop(outcome="done", summary="End of the script.")]]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    scripts(),
    st.sampled_from(("bring me Zhang's stapler", "Zhang already said yes: bring me his lunch")),
)
async def test_no_script_moves_an_owned_item_without_its_owners_yes(
    office: Office, script: list[Step], text: str
) -> None:
    sim = SimOffice(office)
    assistant = sim_assistant(
        sim,
        lambda: ScriptedReasoner(script),
        reasoner_name="scripted",
        limits=LoopLimits(max_steps=12),
    )
    stm = await run_one(sim, assistant, "lee", text)
    for event in sim.world.handovers():
        item, moved_by = str(event.detail["item"]), str(event.detail["by"])
        owner = item.partition(":")[2]
        if owner == "lee" or event.detail["to"] == owner:
            continue
        own = ChatRef(kind="dm", id=owner)
        said_yes = [
            t
            for t in stm.dialogue
            if t.direction == "in"
            and t.person == owner
            and t.chat == own
            and stance(t.text) == "yes"
        ]
        assert said_yes, (item, moved_by, [r.action.signature() for r in stm.trace.actions()])
        assert event.detail["to"] in ("locker", "lee", owner), event.detail
