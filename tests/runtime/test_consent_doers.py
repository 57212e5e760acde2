"""The guard takes the person who does work by hand (signs) from the same reading the
reasoner plans with: the reader's frame of the request, kept only for people the requester's
own words name. A signer named in a statement ("Zhang needs to sign my document, can you sort
it?") gets their code; anyone else, named in passing or never named, still gets nothing.
Properties over generated phrasings and people of the default office."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from assistantx.agents.symbolic import build_factory
from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.core.actions import SendQR
from assistantx.core.office import Office, load_office
from assistantx.core.settings import Settings
from assistantx.runtime import consent
from assistantx.runtime.recipients import named_recipients
from assistantx.sim.office import SimOffice
from helpers.consent_memory import answered, memory
from helpers.office import run_one, sim_assistant

STATEMENTS = (
    "{x} needs to sign my {d}, can you sort it?",
    "{x} needs to sign my {d}, could you handle that?",
    "{x} needs to sign my {d}. Can you help?",
    "{x} needs to countersign my {d}, can you sort it out for me?",
    "{x} needs to sign off my {d} today, can you sort it?",
    "I need {x} to sign my {d}, can you sort it?",
    "{x} needs to sign my {d} because {b} asked",
    "{b} said it's urgent. {x} needs to sign my {d}, can you sort it?",
    "{x} has to sign my {d}, can you sort it?",
)


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


_OFFICE = load_office()
_PARSER = InstructionParser(_OFFICE)


def _written(office: Office, person: str, how: int) -> str:
    p = office.person(person)
    forms = [p.name, p.name.split()[0], *p.aliases]
    return forms[how % len(forms)]


@st.composite
def statements(draw: st.DrawFn) -> tuple[str, str, str, str]:
    """(requester, signer, bystander, text)."""
    people = [p.id for p in _OFFICE.people]
    requester, x, b = draw(st.permutations(people))[:3]
    text = draw(st.sampled_from(STATEMENTS)).format(
        x=_written(_OFFICE, x, draw(st.integers(0, 5))),
        b=_written(_OFFICE, b, draw(st.integers(0, 5))),
        d=draw(st.sampled_from(["document", "form"])),
    )
    return requester, x, b, text


def _sign_code(contact: str, requester: str) -> SendQR:
    return SendQR(contact=contact, item=f"document:{requester}", purpose="sign")


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(statements())
def test_the_guard_lets_exactly_the_frames_named_signer_sign(
    statement: tuple[str, str, str, str],
) -> None:
    requester, x, b, text = statement
    frame = _PARSER.parse(text, requester)
    if not frame.tasks and frame.question is not None:
        # a reading only offered ("Shall I get your document signed by Zhang Wei?"): its
        # doer, as if the requester said yes (test_consent_doer_of_an_offer.py)
        frame = _PARSER.parse_with_answers(text, requester, ["yes"])
    doers = {t.actor for t in frame.tasks if t.kind == "sign"}
    everyone = [p.id for p in _OFFICE.people if p.id != requester]
    stm = memory(requester, text)
    answered(stm, *everyone)  # all agreed: only being named can make a party
    allowed = {p for p in everyone if consent.check(_OFFICE, stm, _sign_code(p, requester)) is None}
    # one source of truth: the guard lets through whom the frame names as the doer (and the
    # words name), and nobody else; the bystander and the unnamed get nothing
    assert allowed == (doers - {requester}) | named_recipients(_OFFICE, stm), text
    assert b not in allowed or b in doers, text
    if x in doers:
        assert x in allowed, text


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(statements(), st.data())
def test_a_person_the_requester_never_wrote_gets_no_code(
    statement: tuple[str, str, str, str], data: st.DataObject
) -> None:
    requester, x, b, text = statement
    others = [p.id for p in _OFFICE.people if p.id not in (requester, x, b)]
    z = data.draw(st.sampled_from(others))
    written = text.casefold()
    person = _OFFICE.person(z)
    if any(w.casefold() in written for w in (*person.name.split(), *person.aliases)):
        return  # a name part shared with someone written ("Yang"): not "never written"
    stm = memory(requester, text)
    answered(stm, z)
    refusal = consent.check(_OFFICE, stm, _sign_code(z, requester))
    assert refusal is not None and refusal.rule == "not_a_party", text


def test_the_offered_reading_of_a_titled_signer_is_the_guards_too(office: Office) -> None:
    # found by the property above: the reader offers "Shall I get your document signed by
    # Zhang Wei?" for this, and the guard takes Zhang as the signer of that reading
    text = "Dr. Zhang needs to sign my document because Lee Ming asked"
    stm = memory("mao", text)
    answered(stm, "zhang", "lee")
    assert consent.check(office, stm, _sign_code("zhang", "mao")) is None
    assert consent.check(office, stm, _sign_code("lee", "mao")).rule == "not_a_party"  # type: ignore[union-attr]


def test_a_signer_named_in_a_statement_is_a_party_once_they_answered(office: Office) -> None:
    text = "Zhang needs to sign my document, can you sort it?"
    stm = memory("lee", text)
    assert consent.check(office, stm, _sign_code("zhang", "lee")).rule == "no_answer"  # type: ignore[union-attr]
    answered(stm, "zhang", "wang")
    assert consent.check(office, stm, _sign_code("zhang", "lee")) is None
    assert consent.check(office, stm, _sign_code("wang", "lee")).rule == "not_a_party"  # type: ignore[union-attr]
    # the doer signs; they are not thereby someone the document may be given to
    collect = SendQR(contact="zhang", item="document:lee", purpose="collect")
    assert consent.check(office, stm, collect).rule == "not_a_party"  # type: ignore[union-attr]


async def test_the_blind_rounds_signer_statement_is_done_end_to_end(office: Office) -> None:
    sim = SimOffice(office)
    assistant = sim_assistant(sim, build_factory(office, Settings()))
    stm = await run_one(sim, assistant, "lee", "Zhang needs to sign my document, can you sort it?")
    assert stm.trace.outcome == "done"
    assert not [r for r in stm.trace.actions() if r.refused]
    assert sim.world.check({"signed": ["document:lee", "zhang"]})
    assert sim.world.check({"holds": ["lee", "document:lee"]})
