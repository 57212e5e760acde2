"""A signer the requester names in a reading the reader only offers ("Shall I get your
document signed by Wang Fang and print your file for you?") is still the signer their words
name: the guard lets that doer have the sign code when a reasoner acts on the reading without
asking (an LLM, the optimal policy), and nobody else. Found when the dataset generator refused
an outside tester's base instruction ("Kwame needs to sign my provisions order, and then print
my delivery schedule for me"): the optimal policy's sign code was refused, so the task failed
with a wording that the plainer "Get Kwame to sign ..." passed."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.core.actions import SendQR
from assistantx.core.office import Office, load_office
from assistantx.core.task_spec import BaseInstruction, Part
from assistantx.evaluation.dataset.generate import generate
from assistantx.runtime import consent
from helpers.consent_memory import answered, exchange, memory

OFFERED = "Wang needs to sign my contract, and then print my timetable for me"


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def _sign(contact: str) -> SendQR:
    return SendQR(contact=contact, item="document:lin", purpose="sign")


def test_the_text_is_read_as_an_offer_not_a_request(office: Office) -> None:
    frame = InstructionParser(office).parse(OFFERED, "lin")
    assert not frame.tasks
    assert frame.question is not None and frame.question.startswith("Shall I")
    assert "Wang Fang" in frame.question


def test_the_offered_signer_gets_the_sign_code_and_no_one_else(office: Office) -> None:
    stm = memory("lin", OFFERED)
    answered(stm, "wang", "zhang")
    assert consent.check(office, stm, _sign("wang")) is None
    refused = consent.check(office, stm, _sign("zhang"))
    assert refused is not None and refused.rule == "not_a_party"
    # the doer signs and the document goes back in the locker: not given to them
    collect = SendQR(contact="wang", item="document:lin", purpose="collect")
    refused = consent.check(office, stm, collect)
    assert refused is not None and refused.rule == "not_a_party"


def test_a_no_to_the_offer_leaves_the_signer_no_party(office: Office) -> None:
    stm = memory("lin", OFFERED)
    question = InstructionParser(office).parse(OFFERED, "lin").question
    assert question is not None
    stm.dialogue.extend(exchange("lin", question, "no", question_id="q-lin"))
    answered(stm, "wang")
    refused = consent.check(office, stm, _sign("wang"))
    assert refused is not None and refused.rule == "not_a_party"


def test_the_generator_keeps_the_offered_wording(office: Office) -> None:
    base = BaseInstruction(
        id="b1",
        requester="lin",
        text=OFFERED,
        parts=(Part(kind="sign", signer="wang"), Part(kind="print")),
    )
    tasks = generate(office, [base], verify=True)  # raises when the optimal policy fails
    assert tasks and all(t.base == "b1" for t in tasks)
